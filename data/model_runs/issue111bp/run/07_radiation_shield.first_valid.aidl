# Request: a radiation shield (a small Stevenson screen) for a weather-station temperature
# and humidity sensor, from 3 mm white acrylic. A stack of six 140 mm plates 18 mm apart (top
# face to top face): a solid top disc with a 6 mm cable hole 25 mm off centre and "TEMP / RH"
# engraved 8 mm high, and five rings of 70 mm bore below it. Three 24 mm wide posts at
# 90, 210 and 330 deg hold the plates without screws: each plate has an 8 mm deep notch at
# each post and each post a 10 mm deep slot for each plate (0.2 mm clearance), so the posts'
# inner edges stand 52 mm from the axis. The posts reach 15 mm above the top disc with a
# 5 mm hanging hole, and 10 mm below the lowest ring; the post at 90 deg reaches 60 mm further
# down with two 5 mm holes (25 mm apart) to screw it to a pole.

import "std/joints.aidl"

thickness 3 mm

T = 3 mm
PLATE_D = 140 mm
BORE = 70 mm
PITCH = 18 mm
PLATES = 6
NOTCH = 8 mm
SLOT = 10 mm
POST_IN = PLATE_D / 2 - NOTCH - SLOT      # 52 mm
POST_W = 24 mm
POST_ANGLES = [90 deg, 210 deg, 330 deg]
TOP = 18 mm                              # the posts' top: 15 mm above the top disc
BOTTOM = -(PLATES - 1) * PITCH - 10 mm   # 10 mm under the lowest ring

def notches() -> hole {
    for i in range(3) {
        n = cross_halving(depth=NOTCH, thickness=T, clearance=0.2 mm,
                          rotation=POST_ANGLES[i] - 90 deg,
                          cx=PLATE_D / 2 * cos(POST_ANGLES[i]), cy=PLATE_D / 2 * sin(POST_ANGLES[i]))
    }
}

def ring_plate() -> solid {
    disc = Circle(center=(0, 0), diameter=PLATE_D)
    hole bore { c = Circle(center=(0, 0), diameter=BORE) }
    cuts = notches()
}

def post(mount=false) -> solid {
    # x: out from the axis, y: up (the top disc's top face at y = 3)
    if mount {
        body = Rectangle(bottom_left=(POST_IN, BOTTOM - 60 mm), width=POST_W, height=TOP - BOTTOM + 60 mm)
        hole pole {
            a = Circle(center=(POST_IN + POST_W / 2, BOTTOM - 20 mm), diameter=5)
            b = Circle(center=(POST_IN + POST_W / 2, BOTTOM - 45 mm), diameter=5)
        }
    } else {
        body = Rectangle(bottom_left=(POST_IN, BOTTOM), width=POST_W, height=TOP - BOTTOM)
    }
    hole hang { c = Circle(center=(POST_IN + POST_W / 2, TOP - 7.5 mm), diameter=5) }
    for k in range(PLATES) {
        s = cross_halving(depth=SLOT, thickness=T, clearance=0.2 mm, rotation=90 deg,
                          cx=POST_IN, cy=-k * PITCH + T / 2)
    }
    Fillet(body.top_left, 4)
    Fillet(body.top_right, 4)
}

assembly shield {
    solid top {
        disc = Circle(center=(0, 0), diameter=PLATE_D)
        hole cable { c = Circle(center=(25, 0), diameter=6) }
        cuts = notches()
        drawing label {
            t = Text("TEMP / RH", position=(0, -20), size=8, valign="middle")
        }
    }
    for k in range(PLATES - 1) {
        ring = ring_plate()
        Place(ring, position=(0, 0, -(k + 1) * PITCH))
    }
    for i in range(3) {
        p = post(mount=(i == 0))
        # stood up in the radial plane at POST_ANGLES[i], centred on it
        Place(p, rotation=(90 deg, 0, POST_ANGLES[i]),
              position=(-T / 2 * sin(POST_ANGLES[i]), T / 2 * cos(POST_ANGLES[i]), 0))
    }
    Place(top, position=(0, 0, 0))

    # on the sheet: the plates in a row, the posts beside them
    for k in range(PLATES - 1) {
        if k == 0 {
            RightOf(ring[k], top, gap=6)
        } else {
            RightOf(ring[k], ring[k - 1], gap=6)
        }
        AlignBottom(ring[k], top)
    }
    for i in range(3) {
        Below(p[i], top, gap=8)
        if i == 0 {
            AlignLeft(p[i], top)
        } else {
            RightOf(p[i], p[i - 1], gap=6)
        }
    }

    # the request's numbers
    assert len(ring) + 1 == 6, "six plates"
    assert top.disc.diameter == 140 mm and ring[0].bore.c.diameter == 70 mm, "plates"
    assert PITCH == 18 mm, "18 mm apart"
    assert len(p) == 3, "three posts"
    assert p[1].body.bb.width == 24 mm, "24 mm posts"
    assert POST_IN == 52 mm, "posts' inner edges 52 mm from the axis (the posts are moved on the sheet)"
    assert p[1].body.bb.top - (p[1].s[0].cut.bb.top - 0.1 mm) == 15 mm, "15 mm above the top"
    assert p[0].body.bb.height - p[1].body.bb.height == 60 mm, "pole post 60 longer"
    assert p[0].pole.a.center.y - p[0].pole.b.center.y == 25 mm, "pole holes 25 apart"
}
