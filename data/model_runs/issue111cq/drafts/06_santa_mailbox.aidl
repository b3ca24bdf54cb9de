# Request: a "Letters to Santa" post box for the mantelpiece, 3 mm birch ply, finger-jointed
# (12 mm fingers), 160 wide x 110 deep x 220 tall outside. It is an open-bottomed box: it stands
# over the letters and is lifted off on Christmas Eve, so five panels: roof, front, back and
# two sides. The roof has a letter slot 120 x 10 mm, centred. The front carries, engraved and
# filled: a 5-point star (outer radius 22, inner 9) at the top, "LETTERS" and "TO SANTA" in a
# bold serif 16 mm tall, and "NORTH POLE" 9 mm single-stroke below; the art block centred on
# the front. Each side has an engraved 6-armed snowflake, 60 mm across, centred.
#
# FIX after the first valid program: the first valid program used finger_box (turned over);
# its assembled view showed both snowflakes on the INSIDE faces of the side panels (the
# template places the sides with their engraved face inward). Rebuilt from five finger_panel
# instances placed by hand, each engraved face outward; the art is now drawn upright.

import "std/joints.aidl"

units mm
thickness 3 mm

t = 3 mm
W = 160 mm
D = 110 mm
H = 220 mm
f = 12 mm

def flake() -> drawing {
    drawing arm {
        spoke = Line((0, 0), (0, 30))
        b1 = Line((0, 18), (-7, 25))
        b2 = Line((0, 18), (7, 25))
        b3 = Line((0, 8), (-5, 13))
        b4 = Line((0, 8), (5, 13))
    }
    arms = CircularPattern(arm, 6, (0, 0))
}

def side() -> solid {
    p = finger_panel(width=D, height=H, thickness=t, finger=f, bottom="flat", right="slots",
                     top="slots", left="slots")
    fl = flake()
    CenterInside(fl, p.outline)
}

assembly santa_mailbox {
    solid roof {
        p = finger_panel(width=W, height=D, thickness=t, finger=f, bottom="slots",
                         right="fingers", top="slots", left="fingers")
        hole letter_slot { s = Slot(center=(0, 0), length=120, width=10) }
        CenterInside(letter_slot, p.outline)
    }
    solid front {
        p = finger_panel(width=W, height=H, thickness=t, finger=f, bottom="flat",
                         right="fingers", top="fingers", left="fingers")
        drawing art {
            star = Star(center=(0, 62), points=5, outer_radius=22, inner_radius=9, fill=true)
            l1 = Text("LETTERS", position=(0, 20), size=16, font="serif:Bold", valign="middle",
                      fill=true)
            l2 = Text("TO SANTA", position=(0, -6), size=16, font="serif:Bold", valign="middle",
                      fill=true)
            l3 = Text("NORTH POLE", position=(0, -32), size=9, valign="middle")
        }
        CenterInside(art, p.outline)
    }
    solid back {
        p = finger_panel(width=W, height=H, thickness=t, finger=f, bottom="flat",
                         right="fingers", top="fingers", left="fingers")
    }
    left_side = side()
    right_side = side()

    # flat on the sheet
    RightOf(back, front, gap=8)
    AlignTop(back, front)
    RightOf(left_side, back, gap=8)
    AlignTop(left_side, front)
    RightOf(right_side, left_side, gap=8)
    AlignTop(right_side, front)
    Below(roof, front, gap=8)
    AlignLeft(roof, front)

    # in 3D: standing on z = 0, open at the bottom, every engraved face outward
    Place(front, position=(0, -D / 2 + t, H / 2), face="front", up="up")
    Place(back, position=(0, D / 2 - t, H / 2), face="back", up="up")
    Place(left_side, position=(-W / 2 + t, 0, H / 2), face="left", up="up")
    Place(right_side, position=(W / 2 - t, 0, H / 2), face="right", up="up")
    Place(roof, position=(0, 0, H - t), face="up")

    # the request's numbers
    assert front.p.outline.width == 160 mm and front.p.outline.height == 220 mm, "front 160 x 220"
    assert left_side.p.outline.width == 110 mm, "110 deep"
    assert roof.letter_slot.s.length == 120 mm and roof.letter_slot.s.width == 10 mm,
        "slot 120 x 10"
    assert front.art.l1.size == 16 mm and front.art.l3.size == 9 mm, "letter sizes"
    assert len(left_side.fl.arms) == 6, "6 arms"
    assert left_side.fl.bb.height == 60 mm, "snowflake 60 across"
}
