# Request: a keycap puller for my mechanical keyboard, cut from 3 mm acrylic. A U-shaped head
# for 1u keycaps (18 mm wide): the prongs' inner faces 19 mm apart, the opening 20 mm deep,
# each prong 5 mm wide, ending in a hook that stands 1.2 mm inward with a flat 1 mm catch on
# top and a 45 degree lead-in under it (so it slides under the keycap's skirt). The head is
# 28 mm tall overall; a handle 22 mm wide runs 70 mm on from the head's top, with a round end
# and a 12 mm finger hole 11 mm from that end. The head's two outer bottom corners rounded
# R2, the opening's inner corners R2. Engraved: "1U" on the head's bridge, "KEYCAP PULLER"
# along the handle.

thickness 3 mm

GAP = 19 mm        # between the prongs' inner faces
DEPTH = 20 mm      # opening depth
PRONG = 5 mm
HEAD_H = 28 mm
HANDLE_W = 22 mm
HANDLE_L = 70 mm
HOOK = 1.2 mm

solid puller {
    half = [(0, DEPTH), (GAP / 2, DEPTH), (GAP / 2, 3), (GAP / 2 - HOOK, 3),
            (GAP / 2 - HOOK, 2), (GAP / 2 + 0.8, 0), (GAP / 2 + PRONG, 0),
            (GAP / 2 + PRONG, HEAD_H), (HANDLE_W / 2, HEAD_H + 6), (0, HEAD_H + 6)]
    head = Polygon(half, mirror="y")
    handle = Slot(start=(0, HEAD_H + 6), end=(0, HEAD_H + HANDLE_L - HANDLE_W / 2),
                  width=HANDLE_W)
    hole finger {
        c = Circle(center=(0, HEAD_H + HANDLE_L - 11 mm), diameter=12)
    }
    drawing marks {
        size_mark = Text("1U", position=(0, (DEPTH + HEAD_H) / 2), size=4, valign="middle")
        name = Text("KEYCAP PULLER", position=(0, HEAD_H + 30 mm), size=3.5, valign="middle",
                    rotation=90 deg, max_width=36 mm)
    }
    Fillet([head.points[6], head.points[12]], 2 mm)
    Fillet([head.points[1], head.points[17]], 2 mm)

    assert head.points[1].x - head.points[17].x == 19 mm, "prongs 19 apart"
    assert head.points[1].y - head.points[6].y == 20 mm, "opening 20 deep"
    assert head.points[6].x - head.points[1].x == 5 mm, "prong 5 wide"
    assert head.points[2].x - head.points[3].x == 1.2 mm, "hook 1.2 inward"
    assert handle.bb.top - head.points[7].y == 70 mm, "handle 70 on from the head"
    assert handle.bb.top - finger.c.center.y == 11 mm, "finger hole 11 from the end"
    assert finger.c.diameter == 12 mm
    assert len(head.points) == 18
}
