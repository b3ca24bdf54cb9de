# Request (gifts): a wooden postcard to post to Gran, 1.5 mm birch ply, A6 (148 x 105 mm,
# 3 mm corner radii). Engraved on its back: "POSTCARD" in filled serif letters 7 mm high at the
# top middle; a divider line down the middle; on the left the message in 4 mm single-stroke
# letters, each line at most 58 mm long ("Dear Gran,", "Wish you were here!", "The sea is
# lovely.", "Love, Tom x"); on the right four 60 mm address lines 12 mm apart with the address
# written on them ("Mrs J. Penrose", "4 Harbour Row", "St Ives", "TR26 1PU"); a 26 x 32 mm stamp
# box 6 mm in from the top right corner, and a round postmark (22 mm, "ST IVES" round its top,
# three wavy lines) overlapping the box's left side. A separate 24 x 30 mm wooden stamp with
# perforated edges (2 mm half-holes at 3 mm pitch: 8 along the top and bottom, 10 down each
# side), an engraved 2.5 mm border, a filled heart and "1st", is glued into the stamp box.

units mm
thickness 1.5 mm

card_w = 148 mm
card_h = 105 mm
box_w = 26 mm
box_h = 32 mm
box_in = 6 mm
stamp_w = 24 mm
stamp_h = 30 mm
perf_d = 2 mm
perf_pitch = 3 mm
box_cx = card_w / 2 - box_in - box_w / 2
box_cy = card_h / 2 - box_in - box_h / 2
address = ["Mrs J. Penrose", "4 Harbour Row", "St Ives", "TR26 1PU"]
message = ["Dear Gran,", "Wish you were here!", "The sea is lovely.", "Love, Tom x"]

assembly postcard {
    solid card {
        body = RoundedRectangle(center=(0, 0), width=card_w, height=card_h, corner_radius=3)
        drawing back {
            title = Text("POSTCARD", position=(0, card_h / 2 - 14), size=7, font="serif",
                         fill=true)
            divider = Line((0, -card_h / 2 + 8), (0, card_h / 2 - 22))
            for i in range(4) {
                msg = Text(message[i], position=(-card_w / 2 + 6, 18 - i * 12), size=4,
                           anchor="start", max_width=58)
                rule = Line((8, -4 - i * 12), (68, -4 - i * 12))
                addr = Text(address[i], position=(10, -2.5 - i * 12), size=4, anchor="start")
            }
            stamp_box = Rectangle(center=(box_cx, box_cy), width=box_w, height=box_h)
            ring = Circle(center=(box_cx - box_w / 2 - 2, box_cy - 4), diameter=22)
            town = Text("ST IVES", along=ring, size=2.5, flip=true)
            for k in range(3) {
                wave = Spline([(box_cx - 44 + 0 * 6, box_cy - 8 + k * 4),
                               (box_cx - 44 + 1 * 6, box_cy - 6.5 + k * 4),
                               (box_cx - 44 + 2 * 6, box_cy - 8 + k * 4),
                               (box_cx - 44 + 3 * 6, box_cy - 9.5 + k * 4),
                               (box_cx - 44 + 4 * 6, box_cy - 8 + k * 4)])
            }
        }
    }

    solid stamp {
        body = Rectangle(center=(0, 0), width=stamp_w, height=stamp_h)
        for k in range(8) {
            hole perf_top { c = Circle(center=(-stamp_w / 2 + 1.5 + k * perf_pitch, stamp_h / 2),
                                       diameter=perf_d) }
            hole perf_bottom { c = Circle(center=(-stamp_w / 2 + 1.5 + k * perf_pitch,
                                                  -stamp_h / 2), diameter=perf_d) }
        }
        for k in range(10) {
            hole perf_left { c = Circle(center=(-stamp_w / 2, -stamp_h / 2 + 1.5 + k * perf_pitch),
                                        diameter=perf_d) }
            hole perf_right { c = Circle(center=(stamp_w / 2, -stamp_h / 2 + 1.5 + k * perf_pitch),
                                         diameter=perf_d) }
        }
        drawing face {
            border = Rectangle(center=(0, 0), width=stamp_w - 5, height=stamp_h - 5)
            heart_l = Hull(Circle(center=(-3, 3), radius=3.4), Point(0, -4.5), fill=true)
            heart_r = Hull(Circle(center=(3, 3), radius=3.4), Point(0, -4.5), fill=true)
            first = Text("1st", position=(0, -10), size=3.5)
        }
    }

    RightOf(stamp, card, gap=10)
    AlignTop(stamp, card)
    Place(card, position=(0, 0, 0))
    # glued into the stamp box
    Place(stamp, position=(box_cx, box_cy, 1.5 mm))

    assert card.body.bb.width == 148 mm and card.body.bb.height == 105 mm, "A6"
    assert card.back.stamp_box.bb.width == 26 mm and card.back.stamp_box.bb.height == 32 mm,
        "stamp box 26 x 32"
    assert card.body.bb.right - card.back.stamp_box.bb.right == 6 mm, "box 6 mm from the right"
    assert card.body.bb.top - card.back.stamp_box.bb.top == 6 mm, "box 6 mm from the top"
    assert stamp.body.bb.width == 24 mm and stamp.body.bb.height == 30 mm, "stamp 24 x 30"
    assert len(stamp.perf_top) == 8 and len(stamp.perf_left) == 10, "8 and 10 perforations"
    assert len(card.back.rule) == 4, "four address lines"
    assert card.back.rule[0].start.y - card.back.rule[1].start.y == 12 mm, "12 mm apart"
    assert card.back.rule[0].length == 60 mm, "60 mm address lines"
    assert card.back.ring.diameter == 22 mm, "22 mm postmark"
    assert card.back.ring.center.x + 11 mm > card.back.stamp_box.bb.left, "postmark overlaps box"
    for i in range(4) {
        assert card.back.msg[i].bb.width <= 58 mm, "message lines at most 58 mm"
        assert card.back.msg[i].bb.right < 0, "message left of the divider"
    }
}
