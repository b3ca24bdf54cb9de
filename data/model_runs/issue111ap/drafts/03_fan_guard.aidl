# Request (electronics): a finger guard for a 120 mm PC fan, 3 mm acrylic. A 120 x 120
# plate with R8 corners; four M4 clearance holes on the fan's 105 mm square; the air passes
# through four rings of curved slots 7 mm wide on radii 22, 32, 42 and 52 mm, six slots a
# ring, left 3 mm apart by six straight radial spokes (and 3 mm rings between the rows);
# the 31 mm hub in the middle is solid with "120" engraved on it.
# FIX after the first valid program: the request's "31 mm hub" was my slip in the request's
# own arithmetic: the 22 mm ring's 7 mm slots leave a solid hub 2 x (22 - 3.5) = 37 mm across,
# as the render shows; the part is right, so only this note and an assert are added.

import "std/fasteners.aidl"

thickness 3 mm

size = 120 mm
hole_square = 105 mm
radii = [22 mm, 32 mm, 42 mm, 52 mm]
per_ring = 6
slot_w = 7 mm
spoke = 3 mm

solid fan_guard {
    plate = RoundedRectangle(center=(0, 0), width=size, height=size, corner_radius=8)
    Fixed(plate)

    screw = clearance_hole(size=4)
    screws = CornerPattern(screw, plate, inset=(size - hole_square) / 2)

    hole air {
        for i in range(len(radii)) {
            for k in range(per_ring) {
                s = ArcSlot(center=(0, 0), radius=radii[i],
                            start_angle=k * 360 deg / per_ring + (spoke + slot_w) / (2 * radii[i]) * 1 rad,
                            end_angle=(k + 1) * 360 deg / per_ring - (spoke + slot_w) / (2 * radii[i]) * 1 rad,
                            width=slot_w)
            }
        }
    }

    drawing label {
        t = Text("120", (0, 0), size=6, valign="middle")
    }

    assert abs(screws[2].c.center.x - screws[0].c.center.x - 105 mm) < 0.001 mm, "holes on a 105 mm square"
    assert abs(screws[2].c.center.y - screws[0].c.center.y - 105 mm) < 0.001 mm, "holes on a 105 mm square"
    assert len(radii) * per_ring == 24, "24 slots"
    assert air.bb.width <= 2 * 52 mm + 7 mm + 0.001 mm, "slots within the 52 mm ring"
    assert plate.bb.width == 120 mm, "120 mm plate"
    assert 2 * (radii[0] - slot_w / 2) == 37 mm, "a 37 mm solid hub (FIX)"
}
