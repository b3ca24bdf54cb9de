# Request: a wall mount for a staghorn fern, from 9 mm exterior ply. A shield-shaped board
# about 260 mm wide and 320 mm tall, flat-topped with rounded shoulders and a point at the
# bottom. Twelve 5 mm lacing holes on an 80 mm radius round the moss ball's centre, 170 mm
# above the point, to tie the fern on with fishing line; "PLATYCERIUM" engraved filled in
# italic serif, 12 mm high, following a 115 mm radius under the ring. On the back, a
# two-layer hanger 180 x 40 centred 270 mm above the point (the wall layer with a keyhole:
# 10 mm head, 5 mm slot running 15 mm up; the layer behind the board with an 11 mm channel
# that clears the screw head) and a two-layer foot 120 x 30 centred 80 mm above the point,
# so the board stands 18 mm off the wall for air behind the moss.

units mm
t = 9 mm
thickness t
import "std/plates.aidl"

ring_y = 170 mm

assembly fern_mount {
    solid board {
        half = [(0, 320), (100, 318), (125, 300), (128, 220), (110, 120), (60, 40), (0, 0)]
        outline = Spline(half, closed=true, mirror="y", corners=[6])
        ring = Circle(center=(0, ring_y), radius=80 mm, construction=true)
        hole lace {
            c = Circle(center=(0, ring_y + 80 mm), diameter=5 mm)
        }
        laces = CircularPattern(lace, 12, ring.center)
        drawing name {
            arc = Circle(center=(0, ring_y), radius=115 mm, construction=true)
            t = Text("PLATYCERIUM", along=arc, flip=true, size=12 mm, font="serif:Italic",
                     fill=true)
        }
    }

    solid hanger_wall {
        r = Rectangle(center=(0, 0), width=180 mm, height=40 mm)
        k = keyhole(head=10 mm, slot_width=5 mm, length=15 mm, direction=90 deg, cx=0, cy=-8 mm)
    }
    solid hanger_mid {
        r = Rectangle(center=(0, 0), width=180 mm, height=40 mm)
        channel = slot(length=15 mm + 11 mm, width=11 mm, rotation=90 deg, cx=0, cy=-8 mm + 7.5 mm)
    }
    solid foot_wall {
        r = Rectangle(center=(0, 0), width=120 mm, height=30 mm)
    }
    solid foot_mid {
        r = Rectangle(center=(0, 0), width=120 mm, height=30 mm)
    }

    # flat on the sheet
    RightOf(hanger_wall, board, gap=10 mm)
    AlignTop(hanger_wall, board)
    Below(hanger_mid, hanger_wall, gap=10 mm)
    AlignLeft(hanger_mid, hanger_wall)
    Below(foot_wall, hanger_mid, gap=10 mm)
    AlignLeft(foot_wall, hanger_mid)
    Below(foot_mid, foot_wall, gap=10 mm)
    AlignLeft(foot_mid, foot_wall)

    # assembled: the board's face to the front, the layers behind it, the wall at y = 18
    Place(board, position=(0, t, 0), face="front", up="up")
    Place(hanger_mid, position=(0, 2 * t, 270 mm), face="front", up="up")
    Place(hanger_wall, position=(0, 3 * t, 270 mm), face="front", up="up")
    Place(foot_mid, position=(0, 2 * t, 80 mm), face="front", up="up")
    Place(foot_wall, position=(0, 3 * t, 80 mm), face="front", up="up")

    assert board.outline.points[0].y - board.outline.points[6].y == 320 mm, "320 mm tall"
    assert board.outline.bb.width >= 250 mm and board.outline.bb.width <= 270 mm, "about 260 wide"
    assert len(board.laces) == 12, "twelve lacing holes"
    assert distance(board.laces[3].c.center, board.ring.center) == 80 mm, "on an 80 mm radius"
    assert board.ring.center.y - board.outline.points[6].y == 170 mm, "ring 170 above the point"
    assert board.lace.c.diameter == 5 mm, "5 mm lacing holes"
    assert distance(board.name, board.laces) >= 8 mm, "name clear of the lacing holes"
    assert hanger_mid.channel.s.width > hanger_wall.k.head_hole.diameter, "channel clears the head"
    assert hanger_mid.channel.s.bb.top >= hanger_wall.k.slot.bb.top + 0.5 mm, "channel covers the slot"
    assert hanger_wall.k.bb.top <= hanger_wall.r.bb.top - 5 mm, "keyhole inside the hanger"
}
