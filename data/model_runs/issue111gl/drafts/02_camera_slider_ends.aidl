# Request: the laser-cut parts of a motorised camera slider on two 8 mm steel rods, 60 mm
# apart (centres) and 500 mm long, cut from 6 mm acrylic. Two end plates, 100 x 80 mm with
# 6 mm corners, each with the two 8 mm rod holes 15 mm up from the bottom edge. The motor
# end carries a NEMA 17 stepper on its outer face: a 22.5 mm hole for its pilot boss, 45 mm
# up, and four M3 clearance holes on its 31 mm square; the idler end has an 8.2 mm hole for
# the M8 bolt of the belt's idler bearing at the same height. "MOTOR" and "IDLER" engraved
# near the top. A carriage plate 100 x 80 mm (6 mm corners) rides on four LM8UU bearings
# (15 mm across, 40 mm apart along each rod), each tied on with a zip tie through two
# 2.5 x 5 mm slots 11 mm either side of the rod; in its centre a 6.5 mm hole for the
# camera's 1/4"-20 screw, and two pairs of M3 holes 16 mm apart, 32 mm from the centre,
# to clamp the belt ends.
# FIX after the first valid program: in the assembled view the belt, on a 20-tooth GT2
# pulley (12.7 mm pitch) at 45 mm, would run 10 mm above the carriage's clamps (its top
# face at 28.5 mm). The shaft goes down to 22 mm so the belt's upper run lies on the
# carriage's top face and the lower run passes under it between the rods.

import "std/fasteners.aidl"

units mm
t = 6 mm
thickness t

rod_d = 8 mm
rod_gap = 60 mm
rod_y = 15 mm
shaft_y = 22 mm
pulley_pitch_r = 6.37 mm
rod_len = 500 mm
bearing_d = 15 mm
tie_x = [-rod_gap / 2 - 11 mm, -rod_gap / 2 + 11 mm, rod_gap / 2 - 11 mm, rod_gap / 2 + 11 mm]
tie_pts = [(x, y) for x in tie_x for y in [-20 mm, 20 mm]]

def end_plate(motor=true) -> solid {
    plate = RoundedRectangle(center=(0, 40), width=100, height=80, corner_radius=6)
    Fixed(plate)
    hole rod_l { c = Circle(center=(-rod_gap / 2, rod_y), diameter=rod_d) }
    hole rod_r { c = Circle(center=(rod_gap / 2, rod_y), diameter=rod_d) }
    if motor {
        hole pilot { c = Circle(center=(0, shaft_y), diameter=22.5) }
        square = Rectangle(center=(0, shaft_y), width=31, height=31, construction=true)
        Fixed(square)
        m3 = clearance_hole(size=3)
        bolts = CornerPattern(m3, square)
        drawing label { word = Text("MOTOR", position=(0, 62), size=6, valign="middle") }
    } else {
        hole axle { c = Circle(center=(0, shaft_y), diameter=8.2) }
        drawing label { word = Text("IDLER", position=(0, 62), size=6, valign="middle") }
    }
}

assembly slider {
    motor_end = end_plate(motor=true)
    idler_end = end_plate(motor=false)

    solid carriage {
        plate = RoundedRectangle(center=(0, 0), width=100, height=80, corner_radius=6)
        Fixed(plate)
        hole camera { c = Circle(center=(0, 0), diameter=6.5) }
        hole ties {
            for p in tie_pts {
                s = Rectangle(center=p, width=2.5, height=5)
            }
        }
        for p in [(-8, -32), (8, -32), (-8, 32), (8, 32)] {
            clamp = clearance_hole(size=3)
            clamp.c.center == p
        }
        assert len(tie_pts) == 8, "two slots for each of four bearings"
        assert ties.s[1].center.y - ties.s[0].center.y == 40 mm, "bearings 40 mm apart along a rod"
        assert clamp[1].c.center.x - clamp[0].c.center.x == 16 mm, "belt clamp holes 16 mm apart"
        assert clamp[0].c.center.y == -32 mm and clamp[2].c.center.y == 32 mm, "clamps 32 mm from the centre"
    }

    # flat on the sheet
    RightOf(idler_end, motor_end, gap=10)
    AlignBottom(idler_end, motor_end)
    RightOf(carriage, idler_end, gap=10)
    AlignBottom(carriage, idler_end)

    # assembled: rods run along +y; the motor end at y = 0, the idler end at the far end,
    # both with their engraved face outwards; the carriage sits on the bearings mid-way
    Place(motor_end, position=(0, 0, 0), face="front", up="up")
    Place(idler_end, position=(0, rod_len, 0), face="back", up="up")
    Place(carriage, position=(0, rod_len / 2, rod_y + bearing_d / 2), face="up", up="back")

    assert motor_end.plate.width == 100 mm and motor_end.plate.height == 80 mm, "end plate 100 x 80"
    assert motor_end.rod_r.c.center.x - motor_end.rod_l.c.center.x == 60 mm, "rods 60 mm apart"
    assert motor_end.rod_l.c.center.y - motor_end.plate.bb.bottom == 15 mm, "rods 15 mm up"
    assert motor_end.pilot.c.center.y - motor_end.plate.bb.bottom == 22 mm, "motor shaft 22 mm up"
    assert motor_end.pilot.c.center.y - 21 mm >= motor_end.plate.bb.bottom, "the 42 mm motor stays above the bottom"
    assert abs(shaft_y + pulley_pitch_r - (rod_y + bearing_d / 2 + t)) <= 0.5 mm,
        "the belt's upper run lies on the carriage's top face"
    assert idler_end.axle.c.center.y == motor_end.pilot.c.center.y, "idler at the motor's height"
    assert motor_end.bolts[2].c.center.x - motor_end.bolts[0].c.center.x == 31 mm, "NEMA 17: 31 mm square"
    assert motor_end.pilot.c.center.y + 21 mm <= motor_end.plate.bb.top, "the 42 mm motor fits under the top"
    assert distance(motor_end.bolts[0].c, motor_end.rod_l.c) >= 3 mm, "bolts clear the rods"
    assert carriage.plate.width == 100 mm and carriage.plate.height == 80 mm, "carriage 100 x 80"
}
