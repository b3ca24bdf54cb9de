# Request (sport, PE teacher): a sit-and-reach flexibility test box, 6 mm birch ply, glued.
# - Box: finger-jointed, open top, 300 mm wide, 350 mm front to back, 320 mm tall (outside),
#   30 mm fingers. A hand-hold 100 x 30 mm with round ends in each side, running front to
#   back, its centre 50 mm below the top edge and centred front to back. "PLACE FEET HERE"
#   engraved filled, bold, 20 mm tall, in the middle of the front panel (the feet side).
# - Top: 300 x 550 mm, glued on, overhanging the front by 150 mm and the back by 50 mm.
#   A 6.5 mm guide slot along its centre line from the 2 cm mark to the 48 cm mark.
#   A scale on both sides of the slot, 0 at the overhanging (front) end: a tick at every
#   cm from 1 to 50, 6 mm long, every 5th 10 mm long, starting 3 mm from the slot's edge;
#   the number at every 5 cm, 6 mm tall, 3 mm beyond the long tick, on both sides.
#   The feet line at 15 cm (over the box's front face) engraved across the plate, from
#   35 mm out from the centre line to 20 mm from each long edge, and "FEET" in 6 mm
#   letters 3 mm above it on the right.
# - Pusher: a 6 mm plate 100 mm long and 60 mm tall overall, its top corners rounded 15 mm,
#   standing on edge along the slot; a tab 60 mm long and 6 mm deep at the front end of its
#   bottom edge rides in the slot. Its front end is read on the scale.
# Assembled: the box on the floor, the top on it, the pusher in the slot at 25 cm.

import "std/joints.aidl"

units mm
thickness 6 mm

assembly sit_and_reach {
    box = finger_box(length=300 mm, depth=350 mm, height=320 mm, thickness=6 mm, finger=30 mm,
                     closed=false)

    hole grip_left { s = Slot(center=(0, 0), length=100, width=30, rotation=90) }
    AlignCenterY(grip_left, box.left)
    grip_left.s.center.x == box.left.bb.left + 50 mm
    CutInto(grip_left, box.left)

    hole grip_right { s = Slot(center=(0, 0), length=100, width=30, rotation=90) }
    AlignCenterY(grip_right, box.right)
    grip_right.s.center.x == box.right.bb.right - 50 mm
    CutInto(grip_right, box.right)

    drawing feet_sign {
        t = Text("PLACE FEET HERE", position=(0, 0), size=20, font="sans:Bold", valign="middle", fill=true)
    }
    CenterInside(feet_sign, box.front)
    CutInto(feet_sign, box.front)

    solid top {
        plate = Rectangle(bottom_left=(-150, 0), width=300, height=550)
        hole guide { s = Slot(center=(0, 250), length=460, width=6.5, rotation=90) }
        drawing scale {
            for c in range(1, 51) {
                right_tick = Line((6.25, c * 10), (6.25 + (10 if c % 5 == 0 else 6), c * 10))
                left_tick = Line((-6.25, c * 10), (-6.25 - (10 if c % 5 == 0 else 6), c * 10))
            }
            for c in range(5, 51, 5) {
                right_num = Text(str(c), position=(19.25, c * 10), size=6, anchor="start", valign="middle")
                left_num = Text(str(c), position=(-19.25, c * 10), size=6, anchor="end", valign="middle")
            }
            feet_right = Line((35, 150), (130, 150))
            feet_left = Line((-35, 150), (-130, 150))
            feet_word = Text("FEET", position=(82.5, 153), size=6)
        }
    }

    solid pusher {
        body = RoundedRectangle(bottom_left=(0, 6), width=100, height=54, corner_radii=[15, 15, 0, 0])
        tab = Rectangle(bottom_left=(0, 0), width=60, height=6)
    }

    # laid out flat for cutting
    RightOf(top, box, gap=10)
    AlignBottom(top, box)
    RightOf(pusher, top, gap=10)
    AlignBottom(pusher, top)

    # assembled (the box places its own panels: centred on x = y = 0, standing on z = 0)
    Place(top, position=(0, -325, 320))
    Place(pusher, position=(-3, -75, 320), face="right", up="up")

    # the request's numbers
    assert box.length == 300 mm and box.depth == 350 mm and box.height == 320 mm, "box 300 x 350 x 320"
    assert box.finger == 30 mm, "30 mm fingers"
    assert grip_left.s.length == 100 mm and grip_left.s.width == 30 mm, "hand-hold 100 x 30"
    assert grip_left.s.center.x - box.left.bb.left == 50 mm, "hand-hold 50 below the top edge"
    assert box.right.bb.right - grip_right.s.center.x == 50 mm, "hand-hold 50 below the top edge"
    assert feet_sign.t.size == 20 mm, "feet sign 20 tall"
    assert feet_sign.bb.width <= box.front.bb.width - 30 mm, "feet sign fits the front"
    assert top.plate.width == 300 mm and top.plate.height == 550 mm, "top 300 x 550"
    assert top.plate.height - 150 mm - 350 mm == 50 mm, "overhangs 150 front, 50 back"
    assert top.guide.s.bb.bottom - top.plate.bb.bottom == 20 mm, "slot from 2 cm"
    assert top.guide.s.bb.top - top.plate.bb.bottom == 480 mm, "slot to 48 cm"
    assert top.guide.s.width == 6.5 mm, "slot 6.5"
    assert len(top.scale.right_tick) == 50 and len(top.scale.left_tick) == 50, "a tick every cm, 1 to 50"
    assert top.scale.right_tick[4].length == 10 mm and top.scale.right_tick[5].length == 6 mm, "5 cm ticks 10, others 6"
    assert top.scale.right_tick[0].start.x - top.guide.s.bb.right == 3 mm, "ticks 3 from the slot"
    assert top.scale.right_tick[14].start.y - top.plate.bb.bottom == 150 mm, "15 cm tick at 150"
    assert len(top.scale.right_num) == 10 and len(top.scale.left_num) == 10, "numbers every 5 cm"
    assert top.scale.right_num[0].position.x - top.scale.right_tick[4].end.x == 3 mm, "numbers 3 beyond the long tick"
    assert top.scale.feet_right.start.y - top.plate.bb.bottom == 150 mm, "feet line at 15 cm"
    assert top.plate.bb.right - top.scale.feet_right.end.x == 20 mm, "feet line 20 from the edge"
    assert distance(top.scale.feet_word, top.scale.right_num) >= 2 mm, "FEET clear of the numbers"
    assert pusher.body.width == 100 mm and pusher.bb.height == 60 mm, "pusher 100 x 60"
    assert pusher.tab.width == 60 mm and pusher.tab.height == 6 mm, "tab 60 x 6"
    assert pusher.tab.bb.left == pusher.body.bb.left, "tab at the front end"
}
