# Request: a tabletop tripod to hang a camping lantern over the picnic table, flat-packing into
# the car, 6 mm plywood. A round hub 120 mm across sits 300 mm above the table on three legs
# 120 deg apart; each leg's top arm reaches from 20 to 95 mm out from the centre, 30 mm deep,
# and a 20 mm tenon (from 30 to 50 mm out) goes up through a slot in the hub; from the arm the
# leg runs down and out to a 30 mm foot whose outer corner is 175 mm from the centre. Outer
# corners rounded r5. A 10 mm hole in the hub's centre takes the lantern's S-hook; "CAMP"
# engraved 8 mm tall on the hub between two of the legs. The lantern (130 across, 200 tall on
# its hook, top 30 mm under the arms) must hang clear of the legs.

import "std/joints.aidl"

thickness 6 mm
T = 6 mm
H = 300 mm           # hub underside above the table
HUB_D = 120 mm
ARM_IN = 20 mm
ARM_OUT = 95 mm
ARM_DEEP = 30 mm
FOOT_OUT = 175 mm
FOOT_W = 30 mm
TENON_MID = 40 mm
LEG_W = 25 mm        # the leg's width where it leaves the arm, along the arm's underside

def leg() -> solid {
    body = Polygon([(ARM_IN, H - ARM_DEEP), (ARM_IN, H), (ARM_OUT, H), (FOOT_OUT, 0),
                    (FOOT_OUT - FOOT_W, 0), (ARM_OUT - LEG_W, H - ARM_DEEP)])
    strip = Rectangle(bottom_left=(TENON_MID - 20, H), width=40, height=T)
    tenon = tab_and_slot(part="tab", length=40 mm, thickness=T, tabs=1, tab=20 mm, screw=0,
                         cx=TENON_MID, cy=H + T)
    Fillet([body.points[2], body.points[3], body.points[4], body.points[5]], 5 mm)
    Fixed(body)
}

assembly tripod {
    solid hub {
        disc = Circle(center=(0, 0), diameter=HUB_D)
        for i in range(3) {
            mortise = tab_and_slot(part="slot", length=40 mm, thickness=T, tabs=1, tab=20 mm,
                                   screw=0, rotation=90 deg + i * 120 deg,
                                   cx=TENON_MID * cos(90 deg + i * 120 deg),
                                   cy=TENON_MID * sin(90 deg + i * 120 deg))
        }
        hole hook { c = Circle(center=(0, 0), diameter=10) }
        drawing label {
            t = Text("CAMP", position=(0, -40), size=8, valign="middle")
        }
        Fixed(disc)
        assert disc.diameter == 120 mm, "hub 120 across"
        assert len(mortise) == 3, "three legs"
    }

    for i in range(3) {
        l = leg()
        Place(l, rotation=(90 deg, 0, 90 deg + i * 120 deg),
              position=(-T / 2 * sin(90 deg + i * 120 deg), T / 2 * cos(90 deg + i * 120 deg), 0))
    }
    Place(hub, position=(0, 0, H))

    # the centre line lies 20 mm inside the arm's inner end (points[0])
    assert l[0].body.points[3].x - (l[0].body.points[0].x - 20 mm) == 175 mm, "foot 175 out"
    assert l[0].body.points[1].y - l[0].body.points[4].y == 300 mm, "hub 300 above the table"
    assert l[0].body.points[3].x - l[0].body.points[4].x == 30 mm, "30 mm foot"
    # lantern clearance: radius 65 + 5 mm air, from 30 mm under the arms down 200 mm
    assert l[0].body.points[5].x - (l[0].body.points[0].x - 20 mm) +
        (l[0].body.points[4].x - l[0].body.points[5].x) * 30 / (H - ARM_DEEP) >= 70 mm,
        "lantern top clears the legs"

    # sheet
    RightOf(l[0], hub, gap=8)
    AlignBottom(l[0], hub)
    RightOf(l[1], l[0], gap=8)
    AlignBottom(l[1], l[0])
    RightOf(l[2], l[1], gap=8)
    AlignBottom(l[2], l[1])
}
