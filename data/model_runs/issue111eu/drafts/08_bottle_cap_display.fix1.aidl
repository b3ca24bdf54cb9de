# Request: a beer-mug bottle cap collector, a birthday gift for a home brewer, in 3 mm
# poplar ply, three layers glued. The mug: a body 220 wide x 280 tall (bottom corners R20),
# a foam head of five R26 bubbles 44 mm apart along the body's top edge, their centres 10 mm
# above it, and a D handle on the right: 80 x 180, fully rounded, centred 125 mm right of the
# body's centre, with a 32 x 120 opening (fully rounded) centred 132 mm right. 42 crown caps
# (26.5 mm) in 27 mm holes, 6 columns x 7 rows on a 32 mm pitch, the block centred across the
# body, the bottom row's centres 115 mm below the body's centre; the holes go through the front
# and middle layers (a 6 mm pocket, the cap's height), the back closes them. Two keyholes in
# the back layer (8 mm head, 4 mm slot 10 mm up) in the foam, 88 mm apart, 10 mm above the
# body's top edge; the middle layer has a 12 mm wide clearance slot over each keyhole's travel
# for the screw head. "CHEERS" engraved filled on the front's foam, bold, 14 mm capitals.
# Every cap hole at least 8 mm from the mug's outline. Laid out flat, 8 mm apart; stacked for
# a look, hung on the wall.

import "std/plates.aidl"

thickness 3 mm

t = 3 mm
body_w = 220 mm
body_h = 280 mm
cap_hole = 27 mm
pitch = 32 mm
rows = 7
cols = 6

# FIX after the first valid program: the keyholes (and the middle layer's clearance slots) sat
# on the body's top line, not 10 mm above it as requested; the assert had been copied from the
# program (== 0 mm) instead of from the request, so nothing caught it.
hang_y = body_h / 2 + 10 mm

def mug(layer="front") -> solid {
    body = RoundedRectangle(center=(0, 0), width=body_w, height=body_h, corner_radii=[0, 0, 20, 20])
    for i in range(5) {
        bubble = Circle(center=((i - 2) * 44 mm, body_h / 2 + 10 mm), radius=26)
    }
    handle = RoundedRectangle(center=(125, 0), width=80, height=180, corner_radius=40)
    hole handle_gap { g = RoundedRectangle(center=(132, 0), width=32, height=120, corner_radius=16) }
    if layer == "front" or layer == "middle" {
        hole cap { c = Circle(center=(-(cols - 1) * pitch / 2, -115), diameter=cap_hole) }
        caps = GridPattern(cap, rows, cols, (pitch, pitch))
    }
    if layer == "middle" {
        hole clear_l { s = Slot(start=(-44, hang_y), end=(-44, hang_y + 10), width=12) }
        hole clear_r { s = Slot(start=(44, hang_y), end=(44, hang_y + 10), width=12) }
    }
    if layer == "back" {
        hang_l = keyhole(head=8 mm, slot_width=4 mm, length=10 mm, direction=90 deg, cx=-44 mm, cy=hang_y)
        hang_r = keyhole(head=8 mm, slot_width=4 mm, length=10 mm, direction=90 deg, cx=44 mm, cy=hang_y)
    }
    if layer == "front" {
        drawing word {
            w = Text("CHEERS", position=(0, body_h / 2 + 10), size=14, font="sans:Bold",
                     valign="middle", fill=true)
        }
    }
}

assembly display {
    back = mug(layer="back")
    middle = mug(layer="middle")
    front = mug(layer="front")

    RightOf(middle, back, gap=8)
    AlignTop(middle, back)
    RightOf(front, middle, gap=8)
    AlignTop(front, back)

    # on the wall (y = 0), front toward -y
    Place(back, position=(0, 0, 0), face="front")
    Place(middle, position=(0, -t, 0), face="front")
    Place(front, position=(0, -2 * t, 0), face="front")

    # the request's numbers
    assert front.body.width == 220 mm and front.body.height == 280 mm, "body 220 x 280"
    assert len(front.bubble) == 5 and front.bubble[0].radius == 26 mm, "five R26 bubbles"
    assert front.bubble[1].center.x - front.bubble[0].center.x == 44 mm, "bubbles 44 apart"
    assert front.bubble[0].center.y - front.body.bb.top == 10 mm, "bubbles 10 above the top"
    assert front.handle.center.x - front.body.center.x == 125 mm, "handle 125 right"
    assert front.handle_gap.g.center.x - front.body.center.x == 132 mm, "opening 132 right"
    assert len(front.caps) == 42 and len(middle.caps) == 42, "42 caps"
    assert front.cap.c.diameter == 27 mm, "27 mm holes"
    assert front.caps[1].c.center.x - front.caps[0].c.center.x == 32 mm and
        front.caps[cols].c.center.y - front.caps[0].c.center.y == 32 mm, "32 mm pitch"
    assert abs((front.caps[0].bb.left - front.body.bb.left) - (front.body.bb.right - front.caps[cols - 1].bb.right)) < 0.01 mm,
        "block centred across the body"
    assert front.body.center.y - front.caps[0].c.center.y == 115 mm, "bottom row 115 below the centre"
    assert front.caps[0].bb.left - front.body.bb.left >= 8 mm, "8 mm to the mug's left side"
    assert front.caps[0].bb.bottom - front.body.bb.bottom >= 8 mm, "8 mm to the bottom"
    assert front.body.bb.right - front.caps[cols - 1].bb.right >= 8 mm, "8 mm to the right side"
    assert back.hang_r.head_hole.center.x - back.hang_l.head_hole.center.x == 88 mm, "keyholes 88 apart"
    assert back.hang_l.head_hole.center.y - back.body.bb.top == 10 mm, "keyholes 10 above the body's top edge"
    assert middle.clear_l.s.start.x == back.hang_l.head_hole.center.x and
        middle.clear_l.s.start.y == back.hang_l.head_hole.center.y, "clearance over the left keyhole"
    assert middle.clear_l.s.width >= back.hang_l.head + 4 mm, "clearance wider than the head"
    assert front.word.w.size == 14 mm, "CHEERS 14 mm"
    assert front.word.bb.width <= 5 * 44 mm - 2 * 10 mm, "CHEERS within the foam"
}
