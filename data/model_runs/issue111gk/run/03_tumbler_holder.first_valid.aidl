# Request: a wall-mounted tumbler holder for the bathroom, 3 mm clear acrylic, solvent-welded.
# A back plate 100 wide x 160 tall with R8 corners, hung by two M4 countersunk screws (4.5 mm
# holes, 9 mm heads) 130 mm apart on its centre line. A ring arm 80 mm wide at the wall with
# a ring of 90 mm outside around a 74 mm opening for the glass, and 70 mm below it (plate to
# plate) a base arm 60 mm wide at the wall with an 80 mm round pad with 19 drain holes of
# 5 mm (one in the middle, 6 on a 32 mm circle, 12 on a 60 mm circle); ring and pad centred
# 47 mm out from the back plate's face, one above the other, the ring 15 mm above the plate's
# middle. Each arm has two tabs (20 mm on the ring arm, 15 mm on the base) into slots in the
# back plate (0.15 mm clearance); R6 fillets where each neck meets its round. Three wavy
# lines 70 mm wide, 6 mm apart, engraved on the back plate above the ring.

import "std/joints.aidl"

thickness 3 mm

assembly tumbler_holder {
    solid back {
        body = RoundedRectangle(center=(0, 0), width=100, height=160, corner_radius=8)
        ring_slots = tab_and_slot(part="slot", length=80 mm, thickness=3 mm, tabs=2,
                                  tab=20 mm, screw=0, clearance=0.15 mm, cx=0 mm, cy=15 mm)
        base_slots = tab_and_slot(part="slot", length=60 mm, thickness=3 mm, tabs=2,
                                  tab=15 mm, screw=0, clearance=0.15 mm, cx=0 mm, cy=-55 mm)
        hole screws {
            top = Circle(center=(0, 65), diameter=4.5)
            bottom = Circle(center=(0, -65), diameter=4.5)
        }
        Countersink(screws, diameter=9 mm)
        drawing wave {
            w = Spline([(-35, 28), (-25, 31), (-15, 28), (-5, 25), (5, 28), (15, 31),
                        (25, 28), (35, 25)])
        }
        waves = LinearPattern(wave, 3, (0, 6))
    }

    # arms drawn with their tab tips on y = 0, reaching out along +y
    solid ring_arm {
        neck = Rectangle(bottom_left=(-40, 0), width=80, height=20)
        disc = Circle(center=(0, 50), radius=45)
        hole opening { c = Circle(center=(0, 50), diameter=74) }
        j = tab_and_slot(part="tab", length=80 mm, thickness=3 mm, tabs=2, tab=20 mm,
                         screw=0, rotation=180 deg, cx=0 mm, cy=0 mm)
        Fillet(neck, disc, 6)
    }

    solid base_arm {
        neck = Rectangle(bottom_left=(-30, 0), width=60, height=20)
        pad = Circle(center=(0, 50), radius=40)
        hole d0 { c = Circle(center=(0, 50), diameter=5) }
        hole d1 { c = Circle(center=(16, 50), diameter=5) }
        hole d2 { c = Circle(center=(30, 50), diameter=5) }
        inner = CircularPattern(d1, 6, (0, 50))
        outer = CircularPattern(d2, 12, (0, 50))
        j = tab_and_slot(part="tab", length=60 mm, thickness=3 mm, tabs=2, tab=15 mm,
                         screw=0, rotation=180 deg, cx=0 mm, cy=0 mm)
        Fillet(neck, pad, 6)
    }

    # on the sheet
    RightOf(ring_arm, back, gap=10)
    AlignTop(ring_arm, back)
    Below(base_arm, ring_arm, gap=10)
    AlignLeft(base_arm, ring_arm)

    # assembled: the wall is y = 0, the back plate in front of it, the arms reaching out
    Place(back, position=(0, 0, 0), face="front", up="up")
    Place(ring_arm, position=(0, 0, 15 - 1.5), face="up", up="front")
    Place(base_arm, position=(0, 0, -55 - 1.5), face="up", up="front")

    assert back.body.bb.width == 100 mm and back.body.bb.height == 160 mm, "100 x 160 back"
    assert back.screws.top.center.y - back.screws.bottom.center.y == 130 mm,
        "screws 130 mm apart"
    assert ring_arm.disc.radius * 2 == 90 mm and ring_arm.opening.c.diameter == 74 mm,
        "a 90 mm ring round a 74 mm opening"
    assert ring_arm.opening.c.center.y - 3 mm == 47 mm, "the glass 47 mm out from the plate"
    assert base_arm.pad.center.y - 3 mm == 47 mm, "the pad under the glass"
    assert base_arm.pad.radius * 2 == 80 mm, "an 80 mm pad"
    assert back.ring_slots.bb.center_y - back.base_slots.bb.center_y == 70 mm,
        "70 mm between ring and base"
    assert back.ring_slots.bb.center_y - back.body.bb.center_y == 15 mm,
        "the ring 15 mm above the middle"
    assert 1 + len(base_arm.inner) + len(base_arm.outer) == 19, "19 drain holes"
    assert distance(back.screws, back.base_slots) >= 3 mm, "the low screw clear of the slots"
    assert len(back.waves) == 3, "three wavy lines"
}
