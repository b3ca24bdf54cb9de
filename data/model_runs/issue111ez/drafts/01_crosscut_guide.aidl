# Request: a crosscut guide (a "T-square") for my circular saw, in 12 mm birch ply.
# The fence is 450 x 80 mm; the saw's base plate runs along its edge. The head, 300 x 50 mm
# with 5 mm chamfers on its corners, is screwed square under the near end of the fence so
# that it hooks over the board's edge, sticking out 110 mm on each side of the fence.
# Four M5 countersunk screws (10 mm heads) through the fence into the head, at 20 mm either
# side of the fence's centre line, 15 and 35 mm from its near end; 3 mm pilot holes in the
# head under them. A 30 mm hanging hole centred 25 mm from the fence's far end.
# Engraved on the fence: a scale along its left edge from the head's inner edge (0) to 350 mm,
# a tick every 10 mm (6 mm long, 12 mm every 50 mm, numbered), and "CROSSCUT 90°" in bold
# filled letters 10 mm high along the fence.

import "std/fasteners.aidl"

thickness 12 mm

fence_w = 80 mm
fence_l = 450 mm
head_w = 300 mm
head_h = 50 mm

assembly saw_guide {
    solid fence {
        body = Rectangle(bottom_left=(-fence_w / 2, 0), width=fence_w, height=fence_l)
        Fixed(body)
        hole screws {
            for p in [(-20, 15), (20, 15), (-20, 35), (20, 35)] {
                s = Circle(center=p, diameter=5.5)
            }
        }
        Countersink(screws.s, diameter=10)
        hole hang {
            c = Circle(center=(0, fence_l - 25), diameter=30)
        }
        drawing scale {
            for i in range(36) {
                t = Line((-fence_w / 2, head_h + i * 10), (-fence_w / 2 + (12 if i % 5 == 0 else 6), head_h + i * 10))
            }
            for j in range(8) {
                n = Text(str(j * 50), position=(-fence_w / 2 + 14, head_h + j * 50), size=4, anchor="start", valign="middle")
            }
        }
        drawing title {
            w = Text("CROSSCUT 90°", position=(12, 240), size=10, rotation=90, valign="middle", font="sans:Bold", fill=true)
        }
    }

    solid head {
        body = Rectangle(bottom_left=(-head_w / 2, 0), width=head_w, height=head_h)
        Fixed(body)
        hole pilots {
            for p in [(-20, 15), (20, 15), (-20, 35), (20, 35)] {
                s = Circle(center=p, diameter=3)
            }
        }
        Chamfer(5)
    }

    # flat on the sheet: head beside the fence
    RightOf(head, fence, gap=10)
    AlignBottom(head, fence)

    # assembled: the head on the bench, the fence screwed on top of it, ends flush
    Place(head, position=(0, 0, 0), face="up")
    Place(fence, position=(0, 0, 12), face="up")

    assert fence.body.bb.width == 80 mm, "fence 80 wide"
    assert fence.body.bb.height == 450 mm, "fence 450 long"
    assert head.body.bb.width == 300 mm, "head 300 long"
    assert head.body.bb.height == 50 mm, "head 50 deep"
    assert len(fence.screws.s) == 4, "four screws"
    assert (head.body.bb.width - fence.body.bb.width) / 2 == 110 mm, "head sticks out 110 each side"
    assert fence.hang.c.diameter == 30 mm, "30 mm hanging hole"
    assert fence.body.bb.top - fence.hang.c.center.y == 25 mm, "hang hole 25 from the far end"
    assert len(fence.scale.t) == 36, "ticks 0..350 every 10"
    assert distance(fence.hang.c, fence.scale) >= 2 mm, "scale clear of the hanging hole"
    assert distance(fence.hang.c, fence.title) >= 2 mm, "title clear of the hanging hole"
}
