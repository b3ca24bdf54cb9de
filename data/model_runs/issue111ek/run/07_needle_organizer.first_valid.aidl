# Request: a wall organizer for circular knitting needles, 3 mm birch ply, 420 wide x 120 tall
# with R8 corners. Along the bottom edge 16 slots, one per needle size (2.0 2.25 2.5 2.75 3.0
# 3.25 3.5 3.75 4.0 4.5 5.0 5.5 6.0 7.0 8.0 9.0 mm), 25 mm apart and centred: each a 4 mm wide
# slot up from the bottom edge, 35 long, ending in an 8 mm round seat the cable rests in (the
# seat's centre 39 up). Each size engraved (single stroke, 5 tall) above its slot, its baseline
# 50 up. CIRCULAR NEEDLES engraved filled (bold serif, 12 tall) centred, baseline 78 up. Two
# keyholes (8 mm head, 4 mm slot 10 long, upward) 370 apart, their heads 100 up, to hang it on
# two screws.

import "std/plates.aidl"

units mm
thickness 3 mm
kerf 0.15 mm

W = 420 mm
H = 120 mm
SIZES = ["2.0", "2.25", "2.5", "2.75", "3.0", "3.25", "3.5", "3.75", "4.0", "4.5", "5.0", "5.5",
         "6.0", "7.0", "8.0", "9.0"]
N = len(SIZES)
PITCH = 25 mm
X0 = -(N - 1) * PITCH / 2     # the first slot's centre

solid organizer {
    body = RoundedRectangle(bottom_left=(0, 0), width=W, height=H, corner_radius=8)
    Fixed(body)

    hole slots {
        for i in range(N) {
            s = Rectangle(corner=(W / 2 + X0 + i * PITCH - 2, 0), opposite=(W / 2 + X0 + i * PITCH + 2, 39))
            mouth = Rectangle(corner=(W / 2 + X0 + i * PITCH - 2, -1), opposite=(W / 2 + X0 + i * PITCH + 2, 0.5),
                              overrun=true)
            seat = Circle(center=(W / 2 + X0 + i * PITCH, 39), diameter=8)
        }
    }

    drawing sizes {
        for i in range(N) {
            t = Text(SIZES[i], position=(W / 2 + X0 + i * PITCH, 50), size=5)
        }
    }

    drawing title {
        t = Text("CIRCULAR NEEDLES", position=(W / 2, 78), size=12, font="serif:Bold", fill=true)
    }

    left_key = keyhole(head=8 mm, slot_width=4 mm, length=10 mm, direction=90 deg,
                       cx=W / 2 - 185 mm, cy=100 mm)
    right_key = keyhole(head=8 mm, slot_width=4 mm, length=10 mm, direction=90 deg,
                        cx=W / 2 + 185 mm, cy=100 mm)

    # the request's numbers
    assert body.width == 420 mm and body.height == 120 mm, "420 x 120"
    assert len(slots.s) == 16 and len(sizes.t) == 16, "16 sizes"
    assert slots.seat[1].center.x - slots.seat[0].center.x == 25 mm, "25 apart"
    assert abs((slots.seat[0].center.x + slots.seat[15].center.x) / 2 - body.bb.center_x) < 0.001 mm, "centred"
    assert slots.s[0].width == 4 mm and slots.seat[0].diameter == 8 mm, "4 mm slot, 8 mm seat"
    assert slots.seat[0].center.y - body.bb.bottom == 39 mm, "seat 39 up"
    assert sizes.t[0].text == "2.0" and sizes.t[15].text == "9.0", "sizes in order"
    assert sizes.t[0].position.y - body.bb.bottom == 50 mm, "sizes 50 up"
    assert title.t.position.y - body.bb.bottom == 78 mm, "title 78 up"
    assert right_key.head_hole.center.x - left_key.head_hole.center.x == 370 mm, "keyholes 370 apart"
    assert left_key.head_hole.center.y - body.bb.bottom == 100 mm, "keyholes 100 up"
    assert distance(sizes, slots) >= 2 mm, "sizes clear of the seats"
    assert distance(title, left_key) >= 3 mm and distance(title, right_key) >= 3 mm, "title clear of the keyholes"
}
