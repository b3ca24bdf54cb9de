# Request: covers for a wedding photo album, 3 mm birch ply, 250 x 250 mm, bound with three
# 5 mm Chicago screws (holes 5.2 mm) 20 mm from the spine edge, in the middle and 90 mm
# above and below it, through both covers and the pages. The front cover folds open on a
# 30 mm living hinge starting 40 mm from the spine edge (pitch 2, 15 mm cuts, 3 mm bridges);
# on its main panel, centred across it: a 100 x 75 mm photo window (5 mm corners) whose
# centre is 25 mm above the cover's middle, "ANNA & TOM" engraved filled in 12 mm serif
# capitals centred 40 mm below the middle, "2026" in 8 mm strokes 62 mm below it, and a
# rounded engraved border 10 mm inside the main panel's edges. The back cover is plain
# with the three holes. Shown assembled on 20 mm of pages, the front opened 60 degrees.

import "std/plates.aidl"

thickness 3 mm

size = 250 mm
spine = 40 mm            # spine strip, edge to the hinge
hinge_w = 30 mm
hole_x = 20 mm
hole_pitch = 90 mm
panel_left = spine + hinge_w
panel_cx = (panel_left + size) / 2

def cover(front=false) -> solid {
    board = Rectangle(bottom_left=(0, -size / 2), width=size, height=size)
    hole binding {
        for j in range(3) {
            c = Circle(center=(hole_x, (j - 1) * hole_pitch), diameter=5.2)
        }
    }
    if front {
        fold = living_hinge(width=hinge_w, height=size, pitch=2 mm, cut=15 mm, bridge=3 mm,
                            cx=spine + hinge_w / 2, cy=0)
        hole window {
            w = RoundedRectangle(center=(panel_cx, 25), width=100, height=75, corner_radius=5)
        }
        drawing words {
            names = Text("ANNA & TOM", position=(panel_cx, -40), size=12, font="serif",
                         valign="middle", fill=true)
            year = Text("2026", position=(panel_cx, -62), size=8, valign="middle")
            border = RoundedRectangle(center=(panel_cx, 0), width=size - panel_left - 20 mm,
                                      height=size - 20 mm, corner_radius=6)
        }
    }
}

assembly album {
    front = cover(front=true)
    back = cover()
    RightOf(back, front, gap=10)
    AlignCenterY(back, front)

    Place(back, position=(0, 0, 0))
    Place(front, position=(0, 0, 3 mm + 20 mm))
    Bend(front, at=spine + hinge_w / 2, angle=60 deg, radius=27 mm)

    assert front.board.bb.width == 250 mm and front.board.bb.height == 250 mm, "250 x 250"
    assert len(front.binding.c) == 3 and len(back.binding.c) == 3, "three binding posts"
    assert front.binding.c[2].center.y - front.binding.c[1].center.y == 90 mm, "90 mm apart"
    assert front.binding.c[0].center.x - front.board.bb.left == 20 mm, "20 mm from the spine"
    assert front.window.w.bb.width == 100 mm and front.window.w.bb.height == 75 mm, "100 x 75 window"
    assert front.window.w.center.y - front.board.center.y == 25 mm, "window 25 mm above the middle"
    assert front.board.center.y - front.words.names.position.y == 40 mm, "names 40 mm below"
    assert front.board.center.y - front.words.year.position.y == 62 mm, "year 62 mm below"
    assert front.fold.bb.left - front.board.bb.left >= 40 mm - 1 mm, "hinge starts 40 mm in"
}
