# Request (music): a limberjack (a jig doll, the folk rhythm toy that dances on a tapped
# paddle), 6 mm ply, seven parts joined by 3 mm steel pins: holes 3.0 mm where a pin is held
# tight and 3.6 mm where a part swings on it.
# - Body: head 40 mm across (centre 150 mm above the hips' origin), a top hat (brim 50 x 4,
#   crown 30 x 24), torso 50 x 80 (R8) centred at 95, shoulder lobes R8 at x +-26, y 124;
#   shoulder pins at (+-26, 124), hip pins at (+-12, 63); an 8 mm hole at the torso's centre
#   for the holding rod (it enters from behind); eyes, smile and two buttons engraved.
# - Two arms: 14 mm wide, 62 mm from the pivot to the wrist, an 18 mm round hand; they hang
#   behind the body.
# - Two thighs: 18 mm wide, hip to knee 50 mm, hanging in front of the body.
# - Two shins: 16 mm wide, knee to ankle 48 mm, a 22 x 14 (R4) clog; they hang in the body's
#   plane below the torso, so the two clogs (24 mm apart centre to centre) must clear each
#   other.

units mm
thickness 6 mm

snug = 3.0
loose = 3.6
t = 6

def arm() -> solid {
    limb = Slot(start=(0, 0), end=(0, -62), width=14)
    hand = Circle(center=(0, -64), diameter=18)
    hole pivot { c = Circle(center=(0, 0), diameter=loose) }
}

def thigh() -> solid {
    limb = Slot(start=(0, 0), end=(0, -50), width=18)
    hole hip { c = Circle(center=(0, 0), diameter=loose) }
    hole knee { c = Circle(center=(0, -50), diameter=snug) }
}

def shin() -> solid {
    limb = Slot(start=(0, 0), end=(0, -48), width=16)
    clog = RoundedRectangle(center=(0, -52), width=22, height=14, corner_radius=4)
    hole knee { c = Circle(center=(0, 0), diameter=loose) }
}

assembly limberjack {
    solid body {
        head = Circle(center=(0, 150), diameter=40)
        brim = Rectangle(center=(0, 168), width=50, height=4)
        crown = Rectangle(center=(0, 180), width=30, height=24)
        torso = RoundedRectangle(center=(0, 95), width=50, height=80, corner_radius=8)
        lobe_l = Circle(center=(-26, 124), radius=8)
        lobe_r = Circle(center=(26, 124), radius=8)
        Fixed(torso)
        for x in [-26, 26] {
            hole shoulder { c = Circle(center=(x, 124), diameter=snug) }
        }
        for x in [-12, 12] {
            hole hip { c = Circle(center=(x, 63), diameter=snug) }
        }
        hole rod { c = Circle(center=(0, 95), diameter=8) }
        drawing face {
            eye_l = Circle(center=(-7, 154), radius=2, fill=true)
            eye_r = Circle(center=(7, 154), radius=2, fill=true)
            smile = Arc(center=(0, 150), radius=10, start_angle=200 deg, end_angle=340 deg)
            b1 = Circle(center=(0, 115), radius=2.5, fill=true)
            b2 = Circle(center=(0, 76), radius=2.5, fill=true)
        }
    }

    arm_l = arm()
    arm_r = arm()
    thigh_l = thigh()
    thigh_r = thigh()
    shin_l = shin()
    shin_r = shin()

    # flat layout: the limbs in a row to the right of the body
    RightOf(arm_l, body, gap=8)
    RightOf(arm_r, arm_l, gap=8)
    RightOf(thigh_l, arm_r, gap=8)
    RightOf(thigh_r, thigh_l, gap=8)
    RightOf(shin_l, thigh_r, gap=8)
    RightOf(shin_r, shin_l, gap=8)
    for p in [arm_l, arm_r, thigh_l, thigh_r, shin_l, shin_r] {
        AlignTop(p, body)
    }

    # 3D: the body's face to the front; arms behind it, thighs in front, shins in its plane
    Place(body, position=(0, t / 2, 0), face="front", up="up")
    Place(arm_l, position=(-26, t / 2 + t, 124), face="front", up="up")
    Place(arm_r, position=(26, t / 2 + t, 124), face="front", up="up")
    Place(thigh_l, position=(-12, -t / 2, 63), face="front", up="up")
    Place(thigh_r, position=(12, -t / 2, 63), face="front", up="up")
    Place(shin_l, position=(-12, t / 2, 13), face="front", up="up")
    Place(shin_r, position=(12, t / 2, 13), face="front", up="up")

    assert body.head.diameter == 40 mm, "head 40"
    assert body.torso.bb.width == 50 mm and body.torso.bb.height == 80 mm, "torso 50 x 80"
    assert body.shoulder[1].c.center.x - body.shoulder[0].c.center.x == 52 mm, "shoulders +-26"
    assert body.hip[1].c.center.x - body.hip[0].c.center.x == 24 mm, "hips +-12"
    assert body.shoulder[0].c.center.y - body.hip[0].c.center.y == 124 mm - 63 mm, "124 vs 63"
    assert body.rod.c.diameter == 8 mm, "8 mm rod hole"
    assert body.shoulder[0].c.diameter == 3.0 mm and arm_l.pivot.c.diameter == 3.6 mm,
        "tight in the body, loose in the arm"
    assert thigh_l.hip.c.diameter == 3.6 mm and thigh_l.knee.c.diameter == 3.0 mm and
        shin_l.knee.c.diameter == 3.6 mm, "thigh swings at the hip, shin at the knee"
    assert arm_l.pivot.c.center.y - arm_l.hand.center.y == 62 mm + 2 mm, "62 to the wrist"
    assert thigh_l.hip.c.center.y - thigh_l.knee.c.center.y == 50 mm, "hip to knee 50"
    assert 24 mm - shin_l.clog.bb.width >= 1 mm, "the clogs clear each other"
    assert body.torso.bb.bottom - (body.hip[0].c.center.y - 50 mm + 9 mm) >= 1 mm,
        "the shins (in the body's plane) stay below the torso"
    assert distance(body.face, body.rod) >= 2 mm, "buttons clear of the rod hole"
}
