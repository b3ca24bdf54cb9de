# Request: a desk zen garden in 3 mm ply. An open-topped finger-jointed tray 200 x 140 x 30
# mm (outside) for fine sand, "BREATHE" engraved filled in a serif face, 10 mm tall, centred
# on the front. A rake: a head 60 x 8 with seven teeth 3 wide and 12 long at 8.5 mm pitch, a
# handle 8 wide standing 90 up from the head's bottom edge with a rounded end and a 4 mm
# hanging hole 6 mm from the end, the handle-to-head corners eased R3. A little arched
# footbridge to stand in the sand: 80 wide, a humped deck 24 high in the middle and 14 at the
# ends, an arch cut out 64 across (radius 32, its centre 20 below the base).

import "std/joints.aidl"

thickness 3 mm

assembly garden {
    box = finger_box(length=200 mm, depth=140 mm, height=30 mm, thickness=3 mm, closed=false)

    drawing word {
        t = Text("BREATHE", position=(0, 0), size=10, font="serif", valign="middle", fill=true)
    }
    CenterInside(word, box.front.core)
    CutInto(word, box.front)

    solid rake {
        head = Rectangle(center=(0, 4), width=60, height=8)
        for i in range(7) {
            tooth = Rectangle(center=(-25.5 + i * 8.5, -5.5), width=3, height=12)
        }
        # FIX after the first valid program: W0406 (fillet only 2.75 mm): the handle ran down to
        # the head's bottom edge, so the Fillet also rounded the gaps beside the middle tooth;
        # the handle now starts 2 mm up, inside the head
        handle = RoundedRectangle(center=(0, 46), width=8, height=88, corner_radius=4)
        hole hang { c = Circle(center=(0, 84), diameter=4) }
        Fillet([handle, head], 3)
    }

    solid bridge {
        deck = Intersect(Circle(center=(0, -60), radius=84),
                         Rectangle(center=(0, 12), width=80, height=24))
        hole arch { c = Circle(center=(0, -20), radius=32) }
    }

    RightOf(rake, box, gap=10)
    AlignBottom(rake, box)
    Above(bridge, rake, gap=10)
    AlignLeft(bridge, rake)

    # in 3D: the rake lies on the sand bed, the bridge stands on the bottom
    Place(rake, position=(60, -30, 3), face="up", up="left")
    Place(bridge, position=(30, 20, 3), face="front", up="up")

    assert box.bottom.outline.bb.width == 200 mm and box.bottom.outline.bb.height == 140 mm,
        "tray 200 x 140"
    assert box.front.outline.bb.height == 30 mm, "tray 30 high"
    assert len(rake.tooth) == 7, "seven teeth"
    assert rake.tooth[1].center.x - rake.tooth[0].center.x == 8.5 mm, "8.5 mm pitch"
    assert rake.head.bb.width == 60 mm, "head 60 wide"
    assert rake.handle.bb.top - rake.head.bb.bottom == 90 mm, "handle 90 up from the head's bottom"
    assert rake.handle.bb.top - rake.hang.c.center.y == 6 mm, "hang hole 6 from the end"
    assert bridge.deck.bb.width == 80 mm, "bridge 80 wide"
    assert bridge.deck.bb.height == 24 mm, "deck 24 high in the middle"
}
