# Request: a rotary card file (a desk "rolodex") for 102 x 57 mm (4 x 2-1/4 in) index cards, cut
# from 4 mm ply. Base 170 x 100 mm with 6 mm corners, "CONTACTS" filled-engraved 10 mm high
# (bold sans) at the front. Two uprights 90 mm wide with a round top (R45), standing 125 mm above
# the base, glued into it with 2 tabs 20 mm wide each, 132 mm apart (centre to centre), each with
# an 8.2 mm hole for the 8 mm dowel axle 80 mm above the base (the round top's centre). Two
# 70 mm hub discs on the dowel, 110 mm apart inside (the cards plus play), each with an 8 mm bore,
# two 5 mm holes 30 mm apart for the brass rails the cards clip onto, and 12 finger notches
# (R4) round the rim; the right-hand disc has "INDEX" engraved 4 mm high over the top.
# Five parts: base, two uprights, two discs.

import "std/joints.aidl"

units mm
thickness 4 mm

T = 4 mm
AXLE_H = 80 mm

def upright() -> solid {
    # tabs reach T below y = 0 (through the base); y = 0 is the base's top face
    body = RoundedRectangle(bottom_left=(-45 mm, -T), width=90 mm, height=T + 125 mm,
                            corner_radii=[45 mm, 45 mm, 0, 0])
    joint = tab_and_slot(part="tab", length=90 mm, thickness=T, tabs=2, tab=20 mm, screw=0,
                         rotation=180 deg, cx=0 mm, cy=-T)
    hole axle { c = Circle(center=(0, AXLE_H), diameter=8.2 mm) }
}

def hub_disc(label="") -> solid {
    body = Circle(center=(0, 0), diameter=70 mm)
    hole bore { c = Circle(center=(0, 0), diameter=8 mm) }
    hole rails {
        a = Circle(center=(-15 mm, 0), diameter=5 mm)
        b = Circle(center=(15 mm, 0), diameter=5 mm)
    }
    hole grip { c = Circle(center=(35 mm, 0), radius=4 mm) }
    grips = CircularPattern(grip, 12, body.center)
    if label != "" {
        drawing name {
            ring = Circle(center=(0, 0), radius=21 mm, construction=true)
            t = Text(label, along=ring, size=4 mm)
        }
    }
}

assembly card_file {
    solid base {
        body = RoundedRectangle(center=(0, 0), width=170 mm, height=100 mm, corner_radius=6 mm)
        left_slot = tab_and_slot(part="slot", length=90 mm, thickness=T, tabs=2, tab=20 mm,
                                 screw=0, rotation=90 deg, cx=-66 mm, cy=0 mm)
        right_slot = tab_and_slot(part="slot", length=90 mm, thickness=T, tabs=2, tab=20 mm,
                                  screw=0, rotation=90 deg, cx=66 mm, cy=0 mm)
        drawing label {
            t = Text("CONTACTS", position=(0, -36 mm), size=10 mm, font="sans:Bold",
                     valign="middle", fill=true)
        }
    }
    left_upright = upright()
    right_upright = upright()
    left_disc = hub_disc()
    right_disc = hub_disc(label="INDEX")

    # flat on the sheet
    RightOf(left_upright, base, gap=8 mm)
    AlignBottom(left_upright, base)
    RightOf(right_upright, left_upright, gap=8 mm)
    AlignBottom(right_upright, left_upright)
    Above(left_disc, base, gap=8 mm)
    AlignLeft(left_disc, base)
    RightOf(right_disc, left_disc, gap=8 mm)
    AlignCenterY(right_disc, left_disc)

    # assembled: uprights stood in the base's slots, discs on the axle between them
    Place(base, position=(0, 0, 0))
    Place(left_upright, position=(-66 mm - T / 2, 0, T), face="right", up="up")
    Place(right_upright, position=(66 mm - T / 2, 0, T), face="right", up="up")
    Place(left_disc, position=(-55 mm - T, 0, T + AXLE_H), face="right", up="up")
    Place(right_disc, position=(55 mm, 0, T + AXLE_H), face="right", up="up")

    # the request's numbers
    assert base.body.bb.width == 170 mm and base.body.bb.height == 100 mm, "base 170 x 100"
    assert right_upright.body.bb.width == 90 mm, "uprights 90 mm wide"
    assert right_upright.body.bb.top - right_upright.joint.bb.top == 125 mm, "125 mm above the base"
    assert right_upright.axle.c.center.y - right_upright.joint.bb.top == 80 mm, "axle 80 mm up"
    assert len(right_upright.joint.gap) - 1 == 2, "2 tabs"
    assert base.right_slot.slot[0].bb.center_x - base.left_slot.slot[0].bb.center_x == 132 mm,
        "uprights 132 mm apart"
    assert right_disc.body.diameter == 70 mm and right_disc.bore.c.diameter == 8 mm, "70 mm discs"
    assert right_disc.rails.b.center.x - right_disc.rails.a.center.x == 30 mm, "rails 30 mm apart"
    assert len(right_disc.grips) == 12, "12 finger notches"
    assert right_upright.axle.c.center.y - right_upright.joint.bb.top > 57 mm + 15 mm,
        "cards clear the base"
}
