# Request: a lid for my enamel camp mug (rim 84 mm inside), 3 mm acrylic, three parts held
# by one M3 Chicago screw at the centre. A 94 mm top disc with two round-ended lifting ears
# sticking out 10 mm left and right (20 mm wide); a plug ring under it, 83.5 mm across
# (0.25 mm clear of the rim all round) and 60 mm inside, that keeps the lid from sliding
# off; a sip slot 14 x 5 mm whose centre is 37 mm from the middle (top), cut through disc and
# ring, and a 3 mm steam vent opposite it; a shutter on top turning on the screw (3.2 mm
# hole) that covers the sip slot: the hull of an 16 mm round at the pivot and a 20 mm round
# over the slot. A mountain skyline and "BASE CAMP" engraved on the lower half of the disc.

thickness 3 mm

sip_r = 37 mm

assembly mug_lid {
    solid top {
        disc = Circle(center=(0, 0), diameter=94)
        ears = Slot(center=(0, 0), length=114, width=20)
        hole pivot { c = Circle(center=(0, 0), diameter=3.2) }
        hole sip { s = Slot(center=(0, sip_r), length=14, width=5) }
        hole vent { c = Circle(center=(0, -sip_r), diameter=3) }
        drawing art {
            peaks = Polyline([(-30, -10), (-18, 5), (-10, -3), (2, 15), (14, -2), (22, 6),
                              (30, -10)])
            word = Text("BASE CAMP", (0, -24), size=6)
        }
    }

    solid ring {
        outer = Circle(center=(0, 0), diameter=83.5)
        hole inner { c = Circle(center=(0, 0), diameter=60) }
        hole sip { s = Slot(center=(0, sip_r), length=14, width=5) }
        hole vent { c = Circle(center=(0, -sip_r), diameter=3) }
    }

    solid shutter {
        paddle = Hull(Circle(center=(0, 0), diameter=16), Circle(center=(0, sip_r), diameter=20))
        hole pivot { c = Circle(center=(0, 0), diameter=3.2) }
    }

    # flat on the sheet
    RightOf(ring, top, gap=8)
    AlignCenterY(ring, top)
    RightOf(shutter, ring, gap=8)
    AlignCenterY(shutter, ring)

    # in 3D: ring in the mug, disc on it, shutter on top
    Place(ring, position=(0, 0, 0))
    Place(top, position=(0, 0, 3))
    Place(shutter, position=(0, 0, 6))

    assert top.disc.diameter == 94 mm, "94 mm disc"
    assert top.ears.length - top.disc.diameter == 2 * 10 mm, "ears 10 mm out"
    assert ring.outer.diameter == 84 mm - 2 * 0.25 mm, "ring 0.25 clear of the rim"
    assert top.sip.s.center.y - top.pivot.c.center.y == 37 mm, "sip slot 37 from the middle"
    assert shutter.paddle.bb.height == 8 mm + 37 mm + 10 mm, "shutter reaches over the slot"
}
