# Soap dish top plate, 4 mm acrylic: 120 x 85 mm, R10 corners; seven drain slots 90 x 5 mm
# (round ends) along the long side, 10 mm apart, centered on the plate; four 4 mm holes for
# rubber-foot pegs, 8 mm in from each corner (both ways).

units mm
thickness 4 mm

param slots = 7, min = 3, max = 8
param pitch = 10 mm, min = 8 mm, max = 12 mm

solid dish {
    plate = RoundedRectangle(center=(0, 0), width=120, height=85, corner_radius=10)

    hole drain {
        s = Slot(center=(0, -(slots - 1) / 2 * pitch), length=90, width=5)
    }
    drains = LinearPattern(drain, slots, (0, pitch))

    hole foot {
        c = Circle(center=(-52, -34.5), diameter=4)
    }
    feet = CornerPattern(foot, plate, inset=8 mm)

    assert abs(plate.bb.width - 120 mm) < 0.001 mm and abs(plate.bb.height - 85 mm) < 0.001 mm, "plate 120 x 85"
    assert len(drains) == 7, "seven slots"
    assert abs(drain.s.length - 90 mm) < 0.001 mm and abs(drain.s.width - 5 mm) < 0.001 mm, "slots 90 x 5"
    assert abs(drains[1].s.center.y - drains[0].s.center.y - 10 mm) < 0.001 mm, "10 mm apart"
    assert abs(drains[3].s.center.y - plate.center.y) < 0.001 mm, "centered"
    assert len(feet) == 4, "four foot holes"
    assert abs(feet[0].c.center.x - plate.bb.left - 8 mm) < 0.001 mm, "8 mm in from the corner"
}
