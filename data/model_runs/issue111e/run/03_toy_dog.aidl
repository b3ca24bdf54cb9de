# Flat-pack toy dog from 3 mm plywood, three parts that slot together crosswise.
# Body (side view): a 140 x 40 mm torso with R12 corners; a 44 mm round head centered on the
# torso's top-left corner; a 5 mm eye hole 8 mm right of and 4 mm above the head's center;
# a tail: an 8 mm wide, 35 mm long slot rising at 45 deg from a point 10 mm below the top
# right corner of the torso. Two cross-halving slots 3 mm wide, 20 mm deep, cut up from the
# torso's bottom edge, 30 mm in from each end of the torso.
# Two identical leg pieces (front view): 60 mm wide, 70 mm tall, R6 top corners, a
# round-topped arch between the legs 30 mm wide and 25 mm tall (R10 at its top corners) cut
# up from the bottom edge, and a cross-halving slot 3 mm wide, 20 mm deep down from the
# middle of the top edge. Assembled, the leg tops sit flush with the torso's top (20 + 20 mm
# = the torso's 40 mm). Parts laid out in a row 10 mm apart for cutting.
units mm
thickness 3 mm
import "std/joints.aidl"

def legs() -> solid {
    frame = RoundedRectangle(center=(0, 0), width=60, height=70, corner_radii=[6, 6, 0, 0])
    hole arch {
        a = RoundedRectangle(center=(0, -22.5), width=30, height=25, corner_radii=[10, 10, 0, 0])
    }
    slot = cross_halving(depth=20 mm, thickness=3 mm, cx=0 mm, cy=35 mm)
}

assembly dog {
    solid body {
        torso = RoundedRectangle(center=(0, 0), width=140, height=40, corner_radius=12)
        solid head {
            c = Circle(center=(-70, 20), diameter=44)
        }
        Concentric(head.c, torso.top_left)
        solid tail {
            s = Slot(start=(70, 10), length=35, angle=45 deg, width=8)
        }
        Coincident(tail.s.start, Point(70, 10, construction=true))
        hole eye {
            e = Circle(center=(-62, 24), diameter=5)
        }
        At(eye.e.center, head.c.center, dx=8, dy=4)
        front_slot = cross_halving(depth=20 mm, thickness=3 mm, rotation=180 deg, cx=-40 mm, cy=-20 mm)
        back_slot = cross_halving(depth=20 mm, thickness=3 mm, rotation=180 deg, cx=40 mm, cy=-20 mm)
    }
    front = legs()
    back = legs()
    RightOf(front, body, gap=10)
    RightOf(back, front, gap=10)
    AlignBottom(front, body)
    AlignBottom(back, body)

    assert body.torso.width == 140 mm and body.torso.height == 40 mm, "torso 140 x 40 mm"
    assert body.head.c.diameter == 44 mm, "head 44 mm"
    assert body.eye.e.diameter == 5 mm, "eye 5 mm"
    assert body.tail.s.length == 35 mm and body.tail.s.width == 8 mm, "tail 35 x 8 mm"
    assert body.front_slot.cut.bb.height == 20 mm and body.front_slot.cut.bb.width == 3 mm, "body slot 3 x 20 mm"
    assert body.front_slot.cut.bb.center_x - body.torso.bb.left == 30 mm, "front slot 30 mm in"
    assert body.torso.bb.right - body.back_slot.cut.bb.center_x == 30 mm, "back slot 30 mm in"
    assert body.front_slot.cut.bb.bottom == body.torso.bb.bottom, "body slots from the bottom edge"
    assert front.frame.width == 60 mm and front.frame.height == 70 mm, "legs 60 x 70 mm"
    assert front.arch.a.width == 30 mm and front.arch.a.height == 25 mm, "arch 30 x 25 mm"
    assert front.slot.cut.bb.height == 20 mm and front.slot.cut.bb.top == front.frame.bb.top, "leg slot 20 mm from the top"
    assert front.slot.cut.bb.height + body.front_slot.cut.bb.height == body.torso.height, "slots add up to the torso"
    assert front.bb.left - body.bb.right == 10 mm, "laid out 10 mm apart"
}
