# Round trivet 180 mm in diameter: three rings of six 8 mm wide arc slots on radii 30, 50
# and 70 mm (slot spines spanning 35, 40 and 40 degrees; the middle ring turned 30 degrees
# so the rings stagger); a 20 mm center hole; outer edge chamfer-free.

param d = 180 mm, min = 150 mm, max = 220 mm

solid trivet {
    disc = Circle(center=(0, 0), diameter=d)
    hole center_hole {
        c = Circle(center=(0, 0), diameter=20)
    }
    hole slots {
        for k in range(6) {
            inner = ArcSlot(center=(0, 0), radius=30, start_angle=k * 60 deg - 17.5 deg,
                            end_angle=k * 60 deg + 17.5 deg, width=8)
            middle = ArcSlot(center=(0, 0), radius=50, start_angle=k * 60 deg + 10 deg,
                             end_angle=k * 60 deg + 50 deg, width=8)
            outer = ArcSlot(center=(0, 0), radius=70, start_angle=k * 60 deg - 20 deg,
                            end_angle=k * 60 deg + 20 deg, width=8)
        }
    }
    assert len(slots.inner) == 6 and len(slots.middle) == 6 and len(slots.outer) == 6, "three rings of six"
    assert slots.outer[0].outer_radius == 74 mm, "outer ring 70 mm radius, 8 mm wide"
    assert disc.diameter == 180 mm, "180 mm trivet"
}
