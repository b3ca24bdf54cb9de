# Request: an anniversary gift: a "record" of 3 mm black acrylic, 300 mm across (an LP),
# with the words of our first-dance song engraved in nine rings, 3.5 mm letters, the rings
# 10 mm apart from 60 mm to 140 mm radius, a thin engraved groove between each ring and the
# next (and outside the last); a centre label 100 mm across, engraved: its outline, "OUR FIRST
# DANCE" round its top, "ANNA & BEN" 6 mm tall and "14 JUNE 2014" 4.5 mm tall across it,
# "SIDE A" round its bottom; a 7.2 mm spindle hole. It stands on the shelf in a stand of the
# same 3 mm acrylic: a base 180 x 60 mm (R5 corners), a back 160 mm wide standing 100 mm
# above the base with R20 top corners, and a front lip 180 mm wide standing 12 mm above it,
# each on two 30 mm tabs glued into mortises in the base (0.1 mm clearance), with 3.5 mm
# between the back and the lip for the record to stand in.

import "std/joints.aidl"

units mm
thickness 3 mm

T = 3 mm
R_DISC = 150 mm
R_LABEL = 50 mm
RINGS = 9
R0 = 60 mm
PITCH = 10 mm
LETTER = 3.5 mm
BACK_H = 100 mm
LIP_H = 12 mm
BACK_Y = 13 mm     # the back's rear face, from the base's middle
LIP_Y = 6.5 mm     # the lip's rear face
GAP = 3.5 mm

LYRICS = [
    "under the lamps of the harbour we were two strangers dancing slow",
    "you said the night was young and I said so are we and the band played on",
    "hold my hand a little longer while the tide rolls in and the lights go low",
    "every step I take is easier with you beside me, every road is home",
    "when the music ends I will still be here, I will still be yours",
    "so spin me round again my love, the record never stops for us",
    "we wrote our names in the sand and the sea forgot them but I never will",
    "one more song, one more turn, one more year of you and me",
    "and when we are old and grey we will dance this dance again",
]

assembly gift {
    solid record {
        disc = Circle(center=(0, 0), radius=R_DISC)
        hole spindle { c = Circle(center=(0, 0), diameter=7.2) }
        drawing grooves {
            for i in range(RINGS) {
                ring = Circle(center=(0, 0), radius=R0 + PITCH * i, construction=true)
                words = Text(LYRICS[i], along=ring, size=LETTER,
                             max_width=0.9 * 2 * pi * (R0 + PITCH * i))
                groove = Circle(center=(0, 0), radius=R0 + PITCH * i + 6.75)
            }
        }
        drawing label {
            edge = Circle(center=(0, 0), radius=R_LABEL)
            top_ring = Circle(center=(0, 0), radius=40, construction=true)
            title = Text("OUR FIRST DANCE", along=top_ring, size=4)
            names = Text("ANNA & BEN", position=(0, 12), size=6, valign="middle")
            date = Text("14 JUNE 2014", position=(0, -14), size=4.5, valign="middle")
            side = Text("SIDE A", along=top_ring, size=4, flip=true)
        }
    }
    Place(record, position=(0, LIP_Y + GAP - (GAP - T) / 2, T + R_DISC), face="front", up="up")

    solid base {
        plate = RoundedRectangle(center=(0, 0), width=180, height=60, corner_radius=5)
        back_slots = tab_and_slot(part="slot", length=160, thickness=T, tabs=2, tab=30, screw=0,
                                  clearance=0.1, cx=0, cy=BACK_Y - T / 2)
        lip_slots = tab_and_slot(part="slot", length=180, thickness=T, tabs=2, tab=30, screw=0,
                                 clearance=0.1, cx=0, cy=LIP_Y - T / 2)
    }
    Place(base, position=(0, 0, 0), face="up")

    solid back {
        body = RoundedRectangle(center=(0, 0), width=160, height=BACK_H + T,
                                corner_radii=[20, 20, 0, 0])
        tabs = tab_and_slot(part="tab", length=160, thickness=T, tabs=2, tab=30, screw=0,
                            rotation=180, cx=0, cy=-(BACK_H + T) / 2)
    }
    Place(back, position=(0, BACK_Y, (BACK_H + T) / 2), face="front", up="up")

    solid lip {
        body = Rectangle(center=(0, 0), width=180, height=LIP_H + T)
        tabs = tab_and_slot(part="tab", length=180, thickness=T, tabs=2, tab=30, screw=0,
                            rotation=180, cx=0, cy=-(LIP_H + T) / 2)
    }
    Place(lip, position=(0, LIP_Y, (LIP_H + T) / 2), face="front", up="up")

    RightOf(back, record, gap=10 mm)
    AlignTop(back, record)
    Below(base, back, gap=10 mm)
    AlignLeft(base, back)
    Below(lip, base, gap=10 mm)
    AlignLeft(lip, base)

    assert record.disc.diameter == 300 mm, "300 mm across"
    assert record.spindle.c.diameter == 7.2 mm, "7.2 mm spindle"
    assert record.label.edge.diameter == 100 mm, "label 100 across"
    assert len(record.grooves.words) == 9, "nine rings"
    assert record.grooves.ring[0].radius == 60 mm and record.grooves.ring[8].radius == 140 mm,
        "60 to 140"
    assert record.grooves.groove[8].radius < record.disc.radius, "last groove on the disc"
    assert record.grooves.ring[0].radius - record.label.edge.radius >= 5 mm,
        "the words clear of the label"
    assert base.plate.bb.width == 180 mm and base.plate.bb.height == 60 mm, "base 180 x 60"
    assert back.body.bb.width == 160 mm and back.body.bb.height - T == 100 mm, "back 100 above"
    assert lip.body.bb.width == 180 mm and lip.body.bb.height - T == 12 mm, "lip 12 above"
    assert (BACK_Y - T) - LIP_Y == 3.5 mm, "3.5 mm for the record"
    assert len(base.back_slots.slot) == 2 and len(base.lip_slots.slot) == 2, "two tabs each"
}
