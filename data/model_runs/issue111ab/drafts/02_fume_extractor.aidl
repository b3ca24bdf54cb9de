# Request (electronics): a bench solder-fume extractor frame for a 120 mm PC fan, 3 mm ply.
# Front plate 180 wide x 140 tall, corners R8. The fan sits centred on the plate: its four
# screw holes 4.5 mm on a 105 mm square; the air opening a honeycomb grille of 8 mm hexagons
# (across flats, points up) on a 10 mm pitch, only whole hexagons inside a 114 mm circle.
# "SOLDER FUMES" engraved upright (reading bottom to top) in the left margin, 6 mm letters.
# Two feet, each 120 long x 50 tall with R5 top corners, cross-halve with the plate: the
# plate has 25 mm slots up from its bottom edge 75 mm either side of the centre (outside the
# fan's 120 mm body), each foot a 25 mm slot down from the middle of its top edge; slots
# 3 mm + 0.1 clearance.

units mm
thickness 3 mm
kerf 0.15 mm

import "std/joints.aidl"

param plate_w = 180 mm, min = 160 mm, max = 220 mm
param plate_h = 140 mm, min = 130 mm, max = 180 mm
fan_holes = 105 mm
grille_d = 114 mm
hex_f = 8 mm
pitch = 10 mm
foot_l = 120 mm
foot_h = 50 mm
halving = 25 mm
foot_x = 75 mm
row_dy = pitch * sqrt(3) / 2
hex_r = hex_f / sqrt(3)

def foot() -> solid {
    body = RoundedRectangle(center=(0, 0), width=foot_l, height=foot_h,
                            corner_radii=[5, 5, 0, 0])
    notch = cross_halving(depth=halving, thickness=3 mm, clearance=0.1 mm,
                          cx=0 mm, cy=foot_h / 2)
}

assembly extractor {
    solid plate {
        body = RoundedRectangle(center=(0, 0), width=plate_w, height=plate_h, corner_radius=8)
        hole screws {
            for i in range(4) {
                c = Circle(center=(fan_holes / 2 * (1 if i % 2 == 0 else -1),
                                   fan_holes / 2 * (1 if i < 2 else -1)), diameter=4.5)
            }
        }
        hole grille {
            for i in range(13) {
                for j in range(13) {
                    x = (j - 6) * pitch + (pitch / 2 if i % 2 == 1 else 0 mm)
                    y = (i - 6) * row_dy
                    if sqrt(x ** 2 + y ** 2) + hex_r <= grille_d / 2 {
                        h = RegularPolygon(center=(x, y), across_flats=hex_f, sides=6,
                                           rotation=30 deg)
                    }
                }
            }
        }
        # FIX after the first valid program: the slots run up from the bottom edge
        # (rotation 180 deg); at 0 they pointed down off the plate (W0502, cut nothing)
        left_slot = cross_halving(depth=halving, thickness=3 mm, clearance=0.1 mm,
                                  rotation=180 deg, cx=-foot_x, cy=-plate_h / 2)
        right_slot = cross_halving(depth=halving, thickness=3 mm, clearance=0.1 mm,
                                   rotation=180 deg, cx=foot_x, cy=-plate_h / 2)
        drawing label {
            t = Text("SOLDER FUMES", position=(-(plate_w / 2 + 60 mm) / 2, 10), size=6,
                     rotation=90 deg, valign="middle")
        }
        assert grille.bb.width <= grille_d, "grille inside the 114 mm circle"
        assert grille.bb.height <= grille_d, "grille inside the 114 mm circle"
        assert label.bb.right < -60 mm, "label clear of the fan"
        assert label.bb.left > body.bb.left + 3 mm, "label on the plate"
        assert label.bb.bottom > -plate_h / 2 + halving + 3 mm, "label above the slots"
    }
    foot_a = foot()
    foot_b = foot()
    Below(foot_a, plate, gap=10)
    Below(foot_b, plate, gap=10)
    # FIX after the first valid program: two 120 mm feet do not fit under a 180 mm plate
    # side by side; they were drawn overlapping. Now side by side, 10 mm apart.
    AlignLeft(foot_a, plate)
    RightOf(foot_b, foot_a, gap=10)

    assert abs(plate.body.bb.width - 180 mm) < 0.01, "plate 180 wide"
    assert abs(plate.body.bb.height - 140 mm) < 0.01, "plate 140 tall"
    assert len(plate.screws.c) == 4, "four fan screws"
    assert abs(plate.screws.c[0].center.x - plate.screws.c[1].center.x) == 105 mm, "105 square"
    assert abs(plate.right_slot.cut.bb.center_x - plate.body.bb.center_x - 75 mm) < 0.01, "slot 75 from centre"
    assert abs(plate.right_slot.cut.bb.height - 25 mm) < 0.01, "plate slot 25"
    assert abs(foot_a.body.bb.width - 120 mm) < 0.01, "foot 120 long"
    assert abs(foot_a.body.bb.height - 50 mm) < 0.01, "foot 50 tall"
    assert abs(foot_a.notch.cut.bb.height + plate.left_slot.cut.bb.height - 50 mm) < 0.01, "halvings add up to the foot height"
    # FIX after the first valid program: this assert was wrong (it held only because the
    # slots pointed off the plate); the slots clear the fan body sideways, not below it
    assert plate.right_slot.cut.bb.left > 60 mm, "slots outside the 120 mm fan body"
    assert abs(plate.right_slot.cut.bb.bottom - plate.body.bb.bottom) < 0.01, "slot opens on the bottom edge"
}
