# Request (holidays): a jointed Halloween skeleton to hang on a door, in 3 mm plywood, the limbs
# joined to the body with 3 mm paper fasteners through 3.5 mm holes.
# Body piece: an oval skull 56 mm wide x 64 mm tall with two 14 mm eye holes (centres 22 mm
# apart), a triangular nose hole 8 mm wide x 9 mm tall, and a jaw 34 mm wide x 20 mm with five
# teeth marked by 10 mm slits 5 mm apart; a 4 mm hanging hole 8 mm below the top of the skull;
# a 10 mm wide spine from the jaw down to the pelvis; a shoulder bar 70 x 12 mm with the shoulder
# holes 58 mm apart; an oval ribcage 64 mm wide x 70 mm tall with four pairs of 5 mm wide rib
# slots 12 mm apart, each running from 3 mm beside the spine out to 3 mm short of the ribcage's
# edge; a pelvis 50 mm wide at the bottom, 30 mm at the top, 24 mm tall, hip holes 32 mm apart.
# Two arms: a 70 mm bone 10 mm wide with a round hand 16 mm across at its end; two legs: a
# 90 mm bone 12 mm wide with a 30 x 10 mm foot pointing outward. Each limb's pivot hole is 6 mm
# below its top. For the assembled view the limbs lie on the body's front face.

thickness 3 mm

pin_d = 3.5 mm
rib_rx = 32 mm
rib_ry = 35 mm
rib_cy = 55 mm
spine_w = 10 mm
def rib_half(y) = rib_rx * sqrt(1 - ((y - rib_cy) / rib_ry) ** 2)   # ribcage half-width at y

def limb(length=70 mm, width=10 mm, kind="arm", side=1) -> solid {
    # the pivot is at (0, 0), 6 mm below the bone's top
    bone = Slot(center=(0, 6 - length / 2), length=length, width=width, rotation=90)
    if kind == "arm" {
        hand = Circle(center=(0, 6 - length - 2), diameter=16)
    } else {
        foot = RoundedRectangle(center=(side * 9, 6 - length + 3), width=30, height=10,
                                corner_radius=4)
    }
    hole pivot {
        c = Circle(center=(0, 0), diameter=pin_d)
    }
}

assembly skeleton {
    solid body {
        skull = Ellipse(center=(0, 150), rx=28, ry=32)
        jaw = RoundedRectangle(center=(0, 118), width=34, height=20, corner_radius=5)
        spine = Rectangle(center=(0, 60), width=spine_w, height=96)
        shoulders = RoundedRectangle(center=(0, 92), width=70, height=12, corner_radius=4)
        ribcage = Ellipse(center=(0, rib_cy), rx=rib_rx, ry=rib_ry)
        pelvis = Trapezoid(center=(0, 0), bottom_width=50, top_width=30, height=24)

        hole eyes {
            l = Circle(center=(-11, 152), diameter=14)
            r = Circle(center=(11, 152), diameter=14)
        }
        hole nose {
            n = Triangle(center=(0, 138), base=8, height=9)
        }
        hole hang {
            h = Circle(center=(0, 150 + 32 - 8), diameter=4)
        }
        cut teeth {
            for i in range(5) {
                s = Line((-10 + i * 5, 109), (-10 + i * 5, 119))
            }
        }
        hole ribs {
            for i in range(4) {
                y = rib_cy + 21 - i * 12
                rl = Slot(start=(-(spine_w / 2 + 3 + 2.5), y), end=(-(rib_half(y) - 3 - 2.5), y),
                          width=5)
                rr = Slot(start=(spine_w / 2 + 3 + 2.5, y), end=(rib_half(y) - 3 - 2.5, y),
                          width=5)
            }
        }
        hole shoulder_pins {
            l = Circle(center=(-29, 92), diameter=pin_d)
            r = Circle(center=(29, 92), diameter=pin_d)
        }
        hole hip_pins {
            l = Circle(center=(-16, -6), diameter=pin_d)
            r = Circle(center=(16, -6), diameter=pin_d)
        }
    }

    left_arm = limb(length=70 mm, width=10 mm, kind="arm", side=-1)
    right_arm = limb(length=70 mm, width=10 mm, kind="arm", side=1)
    left_leg = limb(length=90 mm, width=12 mm, kind="leg", side=-1)
    right_leg = limb(length=90 mm, width=12 mm, kind="leg", side=1)

    # flat on the sheet: the limbs in a row to the right of the body
    RightOf(left_arm, body, gap=8)
    RightOf(right_arm, left_arm, gap=8)
    RightOf(left_leg, right_arm, gap=8)
    RightOf(right_leg, left_leg, gap=8)
    AlignTop(left_arm, body)
    AlignTop(right_arm, body)
    AlignTop(left_leg, body)
    AlignTop(right_leg, body)

    # assembled: each limb's pivot on its pin, on the body's front face
    Place(body, position=(0, 0, 0))
    Place(left_arm, position=(-29, 92, 3))
    Place(right_arm, position=(29, 92, 3))
    Place(left_leg, position=(-16, -6, 3))
    Place(right_leg, position=(16, -6, 3))

    # the request's numbers
    assert body.skull.bb.width == 56 mm and body.skull.bb.height == 64 mm, "skull 56 x 64"
    assert body.eyes.r.center.x - body.eyes.l.center.x == 22 mm, "eyes 22 mm apart"
    assert body.eyes.l.diameter == 14 mm, "14 mm eyes"
    assert body.skull.bb.top - body.hang.h.center.y == 8 mm, "hanging hole 8 mm down"
    assert len(body.teeth.s) == 5, "five teeth"
    assert body.shoulder_pins.r.center.x - body.shoulder_pins.l.center.x == 58 mm,
        "shoulders 58 mm apart"
    assert body.hip_pins.r.center.x - body.hip_pins.l.center.x == 32 mm, "hips 32 mm apart"
    assert body.ribcage.bb.width == 64 mm and body.ribcage.bb.height == 70 mm, "ribcage"
    assert len(body.ribs.rl) == 4 and len(body.ribs.rr) == 4, "four pairs of ribs"
    assert body.ribs.rr[0].center.y - body.ribs.rr[1].center.y == 12 mm, "ribs 12 mm apart"
    assert body.pelvis.bb.width == 50 mm and body.pelvis.bb.height == 24 mm, "pelvis"
    assert left_arm.bone.length == 70 mm and left_leg.bone.length == 90 mm, "bones"
    assert left_arm.bone.bb.top - left_arm.pivot.c.center.y == 6 mm, "pivot 6 mm down"
    assert left_arm.hand.diameter == 16 mm, "16 mm hand"
    assert right_leg.foot.bb.width == 30 mm and right_leg.foot.bb.height == 10 mm, "foot"
}
