# Request: a golf scorecard holder for a folded 100 x 165 mm card, three glued layers, all
# 135 x 180 mm with R8 corners:
# - back, 3 mm plywood, with an R12 thumb notch centred on the pocket at the top edge to push the
#   card up from behind;
# - spacer, 1.5 mm plywood: a pocket 101 mm wide and 166 mm deep open at the top edge, 8 mm from
#   the left edge (so a 14 mm border below it and a 26 mm strip on the right);
# - front, 3 mm plywood: a window R3 showing the card, 5 mm in from the pocket's sides, 24 mm
#   below the top edge and 6 mm above the pocket's bottom; "SCORECARD" (8 mm bold letters,
#   filled) and a flag on a pole engraved in the 24 mm top border.
# Through all three layers: an 8 mm hole for a carabiner in the right strip, 12 mm below the top;
# two pairs of 3 x 12 mm slots for an elastic pencil loop in the right strip, 12 mm apart, their
# middles 50 mm above and 50 mm below the holder's middle.

thickness 3 mm

W = 135 mm
H = 180 mm
POCKET_W = 101 mm
POCKET_D = 166 mm
LEFT = 8 mm
POCKET_L = -W / 2 + LEFT                # the pocket's left edge
POCKET_R = POCKET_L + POCKET_W          # its right edge
POCKET_CX = (POCKET_L + POCKET_R) / 2
STRIP_CX = (POCKET_R + W / 2) / 2       # the middle of the right strip

def layer_outline() -> solid {
    board = RoundedRectangle(center=(0, 0), width=W, height=H, corner_radius=8 mm)
    hole clip {
        c = Circle(center=(STRIP_CX, H / 2 - 12 mm), diameter=8 mm)
    }
    hole pencil {
        for i in range(4) {
            s = Rectangle(center=(STRIP_CX + (6 mm if i % 2 == 1 else -6 mm),
                                  (50 mm if i < 2 else -50 mm)),
                          width=3 mm, height=12 mm)
        }
    }
}

assembly holder {
    solid back {
        o = layer_outline()
        hole thumb {
            c = Circle(center=(POCKET_CX, H / 2), radius=12 mm)
        }
    }
    solid spacer {
        thickness 1.5 mm
        o = layer_outline()
        hole pocket {
            p = Rectangle(corner=(POCKET_L, H / 2 - POCKET_D), opposite=(POCKET_R, H / 2 + 2 mm))
        }
    }
    solid front {
        o = layer_outline()
        hole window {
            w = RoundedRectangle(corner=(POCKET_L + 5 mm, H / 2 - POCKET_D + 6 mm),
                                 opposite=(POCKET_R - 5 mm, H / 2 - 24 mm), corner_radius=3 mm)
        }
        drawing title {
            word = Text("SCORECARD", position=(POCKET_CX + 8 mm, H / 2 - 12 mm), size=8 mm,
                        font="sans:Bold", valign="middle", fill=true)
            pole = Line((POCKET_L + 6 mm, H / 2 - 20 mm), (POCKET_L + 6 mm, H / 2 - 4 mm))
            flag = Polygon([(POCKET_L + 6 mm, H / 2 - 4 mm), (POCKET_L + 16 mm, H / 2 - 8 mm),
                            (POCKET_L + 6 mm, H / 2 - 12 mm)], fill=true)
        }
    }

    # flat on the sheet
    RightOf(spacer, back, gap=8 mm)
    AlignTop(spacer, back)
    RightOf(front, spacer, gap=8 mm)
    AlignTop(front, spacer)

    # in 3D: stacked
    Place(back, position=(0, 0, 0))
    Place(spacer, position=(0, 0, 3 mm))
    Place(front, position=(0, 0, 4.5 mm))

    assert back.o.board.bb.width == 135 mm and back.o.board.bb.height == 180 mm, "135 x 180"
    assert spacer.pocket.p.bb.left - spacer.o.board.bb.left == 8 mm, "pocket 8 from the left"
    assert spacer.pocket.p.bb.width == 101 mm, "pocket 101 wide"
    assert spacer.o.board.bb.top - spacer.pocket.p.bb.bottom == 166 mm, "pocket 166 deep"
    assert spacer.pocket.p.bb.bottom - spacer.o.board.bb.bottom == 14 mm, "14 mm below"
    assert spacer.o.board.bb.right - spacer.pocket.p.bb.right == 26 mm, "26 mm strip"
    assert front.window.w.bb.left - (front.o.board.bb.left + 8 mm) == 5 mm and
        (front.o.board.bb.left + 8 mm + 101 mm) - front.window.w.bb.right == 5 mm,
        "window 5 in from the pocket's sides"
    assert front.o.board.bb.top - front.window.w.bb.top == 24 mm, "24 mm top border"
    assert front.window.w.bb.bottom - (front.o.board.bb.top - 166 mm) == 6 mm,
        "window 6 above the pocket's bottom"
    assert back.thumb.c.radius == 12 mm and back.thumb.c.center.x == back.o.board.bb.left + 8 mm + 101 mm / 2,
        "R12 thumb notch over the pocket"
    assert back.o.clip.c.diameter == 8 mm, "8 mm carabiner hole"
    assert back.o.board.bb.top - back.o.clip.c.center.y == 12 mm, "12 below the top"
    assert len(back.o.pencil.s) == 4, "two pairs of slots"
    assert back.o.pencil.s[0].bb.width == 3 mm and back.o.pencil.s[0].bb.height == 12 mm, "3 x 12"
    assert back.o.pencil.s[1].bb.center_x - back.o.pencil.s[0].bb.center_x == 12 mm, "12 apart"
    assert back.o.pencil.s[0].bb.center_y - back.o.board.bb.center_y == 50 mm and
        back.o.board.bb.center_y - back.o.pencil.s[2].bb.center_y == 50 mm, "50 above and below"
    assert distance(spacer.o.pencil, spacer.pocket) >= 4 mm, "slots clear of the pocket"
    assert distance(spacer.o.clip, spacer.pocket) >= 4 mm, "clip hole clear of the pocket"
    assert distance(front.title, front.window) >= 2 mm, "title clear of the window"
    assert front.title.bb.top <= front.o.board.bb.top - 2 mm, "title inside the top border"
    assert front.title.bb.right <= front.o.board.bb.left + 8 mm + 101 mm, "title over the pocket"
}
