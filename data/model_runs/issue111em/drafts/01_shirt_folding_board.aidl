# Request: a kids' T-shirt folding board, laser-cut in one piece from 3 mm birch ply
# (bed 600 x 400 mm). Overall 570 x 300 mm with R10 outer corners: a centre panel 180 mm
# wide between a left and a right flap, each 180 mm wide, joined to it by a living-hinge
# band 15 mm wide running the full 300 mm height (cuts 15 mm long, 3 mm bridges, 2 mm
# pitch), so each flap folds 180 degrees over the centre. A finger slot 40 x 14 mm,
# upright, centred 20 mm in from each flap's outer edge, at mid height, to lift the flap.
# Engraved on the top face: a big "1" on the left flap and "2" on the right flap (40 mm
# tall), a fold line across the centre panel 100 mm above its bottom edge with "3" (30 mm)
# under it, and "COLLAR" (10 mm) 20 mm below the top edge of the centre panel.

units mm
thickness 3 mm

import "std/plates.aidl"

param panel_w = 180 mm, min = 120 mm, max = 185 mm
param board_h = 300 mm, min = 200 mm, max = 380 mm
param band_w = 15 mm, min = 10 mm, max = 20 mm

total_w = 3 * panel_w + 2 * band_w

assembly folder {
    solid board {
        body = RoundedRectangle(center=(0, 0), width=total_w, height=board_h, corner_radius=10)
        left_hinge = living_hinge(width=band_w, height=board_h, pitch=2, cut=15, bridge=3,
                                  cx=-(panel_w + band_w) / 2, cy=0)
        right_hinge = living_hinge(width=band_w, height=board_h, pitch=2, cut=15, bridge=3,
                                   cx=(panel_w + band_w) / 2, cy=0)
        hole grips {
            left = Slot(center=(-total_w / 2 + 20, 0), length=40, width=14, rotation=90)
            right = Slot(center=(total_w / 2 - 20, 0), length=40, width=14, rotation=90)
        }
        drawing guide {
            one = Text("1", position=(-(panel_w + band_w), 0), size=40, valign="middle")
            two = Text("2", position=(panel_w + band_w, 0), size=40, valign="middle")
            fold = Line((-panel_w / 2 + 10, -board_h / 2 + 100), (panel_w / 2 - 10, -board_h / 2 + 100))
            three = Text("3", position=(0, -board_h / 2 + 50), size=30, valign="middle")
            collar = Text("COLLAR", position=(0, board_h / 2 - 20), size=10, valign="middle")
        }
        Fixed(body)
    }
    Place(board, position=(0, 0, 0), face="up")
    # show the right flap folding: 90 degrees about the middle of its hinge band
    Bend(board, at=(panel_w + band_w) / 2, angle=90 deg, radius=15 / pi - 1.5)

    # the request's numbers, copied from it
    assert board.body.width == 570 mm, "570 mm overall"
    assert board.body.height == 300 mm, "300 mm tall"
    assert board.body.width <= 600 mm and board.body.height <= 400 mm, "fits the bed"
    assert board.right_hinge.bb.left - board.left_hinge.bb.right >= 180 mm, "centre panel 180 wide"
    assert board.grips.left.center.x - board.body.bb.left == 20 mm, "left slot 20 in"
    assert board.body.bb.right - board.grips.right.center.x == 20 mm, "right slot 20 in"
    assert board.guide.fold.start.y - board.body.bb.bottom == 100 mm, "fold line 100 up"
    assert board.body.bb.top - board.guide.collar.position.y == 20 mm, "collar 20 below top"
}
