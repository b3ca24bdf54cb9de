# Request (workshop): a pair of drawer-slide installation jigs in 6 mm birch ply. Each jig is a
# spacer 120 mm high that stands on the cabinet floor against the side panel, so the slide laid
# on its top edge is screwed on at exactly 120 mm. The spacer is 350 mm long behind a front stop;
# its front end goes through the stop on two glued tenons 25 mm wide (flush with the stop's
# front face). The stop is 50 x 120 mm with 4 mm rounded corners, the spacer centred across it
# (22 mm overhang each side, enough to hook over an 18 mm cabinet side, left or right). In the
# spacer: a 90 x 30 mm hand hole; engraved ticks along the top edge every 32 mm from the stop's
# back face (32 ... 320, numbered) for the slide's screw holes; the title "DRAWER SLIDE JIG 120"
# in filled letters 10 mm high and an arrow with "FRONT" pointing at the stop.

import "std/joints.aidl"

thickness 6 mm

T = 6 mm          # the ply
H = 120 mm        # the slide's height above the floor
L = 350 mm        # spacer length behind the stop
W_STOP = 50 mm
TENON = 25 mm
PITCH = 32 mm

def spacer_part() -> solid {
    body = Rectangle(center=(0, 0), width=L + T, height=H)
    # tenons on the front (left) end, through the stop
    j = tab_and_slot(part="tab", length=H, thickness=T, tabs=2, tab=TENON, screw=0,
                     rotation=90 deg, cx=-(L + T) / 2, cy=0)
    hole grip {
        s = Slot(center=(40, 15), length=90, width=30)
    }
    drawing marks {
        for k in range(1, 11) {
            tick = Line((-(L + T) / 2 + T + k * PITCH, H / 2), (-(L + T) / 2 + T + k * PITCH, H / 2 - 8))
            num = Text(str(k * 32), position=(-(L + T) / 2 + T + k * PITCH, H / 2 - 14), size=4)
        }
        title = Text("DRAWER SLIDE JIG 120", position=(0, -40), size=10, font="sans:Bold",
                     fill=true)
        arrow = Polygon([(-160, 10), (-140, 18), (-140, 2)], fill=true)
        front = Text("FRONT", position=(-135, 10), size=7, anchor="start", valign="middle")
    }
}

def stop_part() -> solid {
    body = RoundedRectangle(center=(0, 0), width=W_STOP, height=H, corner_radius=4)
    j = tab_and_slot(part="slot", length=H, thickness=T, tabs=2, tab=TENON, screw=0,
                     rotation=90 deg, cx=0, cy=0)
}

assembly jigs {
    for i in range(2) {
        spacer = spacer_part()
        stop = stop_part()
        # spacer on edge along the cabinet side (its engraving looking +x), front end at y = 0
        Place(spacer, position=(i * 450 mm, (L + T) / 2, H / 2), face="right", up="up")
        # stop across the front, its front face flush with the tenons' tips
        Place(stop, position=(i * 450 mm + T / 2, T, H / 2), face="front", up="up")
    }
    # flat on the sheet: spacers one above the other, the stops to their right
    Below(spacer[1], spacer[0], gap=10)
    AlignLeft(spacer[1], spacer[0])
    RightOf(stop[0], spacer[0], gap=10)
    AlignTop(stop[0], spacer[0])
    RightOf(stop[1], stop[0], gap=10)
    AlignTop(stop[1], stop[0])

    assert len(spacer) == 2, "a pair of jigs"
    assert len(stop) == 2, "a stop for each"
    assert spacer[0].body.bb.height == 120 mm, "the slide sits at 120 mm"
    assert spacer[0].body.bb.width - 6 mm == 350 mm, "350 mm behind the 6 mm stop"
    assert stop[0].body.bb.width == 50 mm and stop[0].body.bb.height == 120 mm, "stop 50 x 120"
    assert (stop[0].body.bb.width - 6 mm) / 2 == 22 mm, "22 mm overhang each side"
    assert spacer[0].grip.s.length == 90 mm and spacer[0].grip.s.width == 30 mm, "hand hole"
    assert len(spacer[0].marks.tick) == 10, "ticks 32 ... 320"
    assert spacer[0].marks.tick[9].start.x - (spacer[0].body.bb.left + 6 mm) == 320 mm,
        "last tick at 320 from the stop's back face"
    assert distance(spacer[0].marks.title, spacer[0].grip) >= 3 mm, "title clear of the hand hole"
}
