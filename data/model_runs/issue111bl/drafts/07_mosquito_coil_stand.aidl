# Request (camping): a mosquito-coil holder for the tent porch, 3 mm ply. A base disc and a cover
# disc, both 160 mm across, held 40 mm apart (clear) by three legs 20 mm wide on a 72 mm radius
# (at 90, 210 and 330 degrees), each leg with one 10 mm tab into each disc (mortises 0.1 mm
# clearance). The base has a 12 x 1.2 mm slit in its centre for the coil's metal clip. The cover
# lets the smoke out: a 30 mm hole in the middle and a honeycomb of 8 mm hexagonal vents (3 mm
# webs) out to 52 mm from the centre; "KEEP CLEAR OF TENT" engraved 5 mm tall round its lower rim,
# readable from the front, on a 66 mm radius.

import "std/joints.aidl"

thickness 3 mm

t = 3 mm
disc_d = 160 mm
gap = 40 mm
leg_w = 20 mm
leg_r = 72 mm
angles = [90 deg, 210 deg, 330 deg]
hex_af = 8 mm
web = 3 mm
pitch = hex_af + web
row = pitch * sqrt(3) / 2
vent_r = 52 mm
smoke_d = 30 mm

def hx(r, c) = c * pitch + (r % 2) * pitch / 2
def hy(r) = r * row
def mortises() -> hole {
    for a in angles {
        m = tab_and_slot(part="slot", length=leg_w, thickness=t, tabs=1, tab=10, screw=0,
                         clearance=0.1, rotation=a + 90 deg, cx=leg_r * cos(a),
                         cy=leg_r * sin(a))
    }
}

solid base_disc() {
    body = Circle(center=(0, 0), diameter=disc_d)
    legs = mortises()
    hole clip { s = Rectangle(center=(0, 0), width=12, height=1.2) }
}

solid cover_disc() {
    body = Circle(center=(0, 0), diameter=disc_d)
    legs = mortises()
    hole smoke { c = Circle(center=(0, 0), diameter=smoke_d) }
    for r in range(-6, 7) {
        for c in range(-6, 7) {
            if sqrt(hx(r, c) ** 2 + hy(r) ** 2) <= vent_r and
                sqrt(hx(r, c) ** 2 + hy(r) ** 2) >= smoke_d / 2 + web + hex_af / sqrt(3) {
                hole vent {
                    h = RegularPolygon(center=(hx(r, c), hy(r)), across_flats=hex_af, sides=6,
                                       rotation=30 deg)
                }
            }
        }
    }
    drawing warning {
        rim = Circle(center=(0, 0), radius=66, construction=true)
        txt = Text("KEEP CLEAR OF TENT", along=rim, flip=true, size=5)
    }
}

def leg_part() -> solid {
    body = Rectangle(center=(0, 0), width=leg_w, height=gap + 2 * t)
    top = tab_and_slot(part="tab", length=leg_w, thickness=t, tabs=1, tab=10, screw=0,
                       cx=0, cy=gap / 2 + t)
    bottom = tab_and_slot(part="tab", length=leg_w, thickness=t, tabs=1, tab=10, screw=0,
                          rotation=180, cx=0, cy=-gap / 2 - t)
}

assembly holder {
    base = base_disc()
    cover = cover_disc()
    for i in range(3) {
        leg = leg_part()
        Place(leg, rotation=(90 deg, 0, angles[i] + 90 deg),
              position=((leg_r - t / 2) * cos(angles[i]), (leg_r - t / 2) * sin(angles[i]),
                        t + gap / 2))
    }

    RightOf(cover, base, gap=5)
    AlignBottom(cover, base)
    RightOf(leg[0], cover, gap=5)
    AlignBottom(leg[0], cover)
    RightOf(leg[1], leg[0], gap=5)
    AlignBottom(leg[1], leg[0])
    RightOf(leg[2], leg[1], gap=5)
    AlignBottom(leg[2], leg[1])

    Place(base, position=(0, 0, 0))
    Place(cover, position=(0, 0, t + gap))

    # the request's numbers
    assert base.body.diameter == 160 mm and cover.body.diameter == 160 mm, "discs 160"
    assert len(leg) == 3, "three legs"
    assert leg[0].top.gap[0].bb.bottom - leg[0].bottom.gap[0].bb.top == 40 mm, "40 clear"
    assert leg[0].body.bb.width == 20 mm, "legs 20 wide"
    assert distance(base.legs.m[0].slot[0].bb.center, base.body.center) == 72 mm, "72 radius"
    assert cover.smoke.c.diameter == 30 mm, "30 mm smoke hole"
    assert base.clip.s.bb.width == 12 mm and base.clip.s.bb.height == 1.2 mm, "clip slit"
}
