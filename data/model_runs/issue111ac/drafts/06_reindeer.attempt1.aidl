# Holidays: a slot-together Christmas reindeer for the mantelpiece, cut from 3 mm ply. The
# body in side view: a torso 120 x 40 mm (R18 ends), a neck rising forward to an oval head
# (40 x 26 mm, tilted 15 deg nose-down) with a round 12 mm nose, a 3 mm eye hole, a short
# upturned tail, a 14 x 14 mm post on top of the head to carry the antlers, and "RUDOLPH"
# engraved on the torso in 8 mm single-stroke letters. Two identical leg pieces (95 mm tall,
# 50 mm wide at the top, 70 mm at the ground, an arch 36 mm wide and 50 mm high from the
# ground with R14 corners leaving two legs) cross the torso 35 mm in front of its middle and
# 40 mm behind it: halvings 20 mm from the torso's bottom and 20 mm from each leg piece's
# top (20 + 20 = the torso's 40 mm). An antler piece about 90 mm wide (two beams with two
# tines each, on a 30 x 12 mm base) crosses the head post: halvings 6 + 6 = 12 mm. All
# halving slots 3.1 mm wide (0.1 clearance). Assembly of 4 parts.

units mm
thickness 3 mm
import "std/joints.aidl"

param t = 3 mm, min = 2 mm, max = 4 mm
param fit = 0.1 mm, min = 0 mm, max = 0.3 mm
param torso_l = 120 mm, min = 100 mm, max = 160 mm
param torso_h = 40 mm, min = 30 mm, max = 50 mm
param leg_h = 95 mm, min = 70 mm, max = 130 mm

def legs() -> solid {
    frame = Trapezoid(center=(0, -leg_h / 2), bottom_width=70, top_width=50, height=leg_h)
    hole arch {
        a = RoundedRectangle(center=(0, -leg_h + 45 / 2 - 5 / 2), width=36, height=55,
                             corner_radii=[14, 14, 0, 0])
    }
    notch = cross_halving(depth=torso_h / 2, thickness=t, clearance=fit, cx=0 mm, cy=0 mm)
}

def antler_piece() -> solid {
    base = Rectangle(center=(0, 6), width=30, height=12)
    for s in range(2) {
        beam = Slot(start=((2 * s - 1) * 8, 8), end=((2 * s - 1) * 40, 44), width=7)
        tine1 = Slot(start=((2 * s - 1) * 20, 22), end=((2 * s - 1) * 14, 46), width=6)
        tine2 = Slot(start=((2 * s - 1) * 30, 33), end=((2 * s - 1) * 26, 54), width=5)
    }
    notch = cross_halving(depth=6 mm, thickness=t, clearance=fit, rotation=180 deg, cx=0 mm,
                          cy=0 mm)
}

assembly reindeer {
    solid body {
        torso = RoundedRectangle(center=(0, 0), width=torso_l, height=torso_h, corner_radius=18)
        neck = Slot(start=(42, 8), end=(62, 48), width=24)
        head = Ellipse(center=(74, 54), rx=20, ry=13, rotation=-15 deg)
        nose = Circle(center=(93, 47), diameter=12)
        post = Rectangle(center=(70, 68), width=14, height=14)
        tail = Slot(start=(-50, 8), end=(-68, 24), width=8)
        hole eye {
            c = Circle(center=(78, 58), diameter=3)
        }
        front = cross_halving(depth=torso_h / 2, thickness=t, clearance=fit, rotation=180 deg,
                              cx=35 mm, cy=-torso_h / 2)
        back = cross_halving(depth=torso_h / 2, thickness=t, clearance=fit, rotation=180 deg,
                             cx=-40 mm, cy=-torso_h / 2)
        antler_slot = cross_halving(depth=6 mm, thickness=t, clearance=fit, cx=70 mm, cy=75 mm)
        drawing name {
            w = Text("RUDOLPH", position=(-5, -3), size=8)
        }
    }
    front_legs = legs()
    back_legs = legs()
    antlers = antler_piece()

    # laid out flat for cutting
    RightOf(front_legs, body, gap=8)
    RightOf(back_legs, front_legs, gap=8)
    AlignTop(front_legs, body)
    AlignTop(back_legs, body)
    Below(antlers, body, gap=8)
    AlignLeft(antlers, body)

    # the request's own numbers
    assert body.torso.width == 120 mm and body.torso.height == 40 mm, "torso 120 x 40"
    assert body.head.rx * 2 == 40 mm and body.head.ry * 2 == 26 mm, "head 40 x 26"
    assert body.nose.diameter == 12 mm and body.eye.c.diameter == 3 mm, "12 mm nose, 3 mm eye"
    assert body.post.width == 14 mm and body.post.height == 14 mm, "14 mm head post"
    assert body.front.cut.bb.center_x - body.torso.center.x == 35 mm, "front legs 35 mm ahead"
    assert body.torso.center.x - body.back.cut.bb.center_x == 40 mm, "back legs 40 mm behind"
    assert body.front.depth + front_legs.notch.depth == 40 mm, "leg halvings fill the torso's 40 mm"
    assert body.antler_slot.depth + antlers.notch.depth == 12 mm, "antler halvings 6 + 6"
    assert front_legs.frame.height == 95 mm, "legs 95 mm tall"
    assert front_legs.frame.top_width == 50 mm and front_legs.frame.bottom_width == 70 mm, "legs 50 at the top, 70 at the ground"
    assert front_legs.arch.a.bb.top - front_legs.frame.bb.bottom == 50 mm, "arch 50 mm high"
    assert front_legs.arch.a.width == 36 mm, "arch 36 mm wide"
    assert antlers.bb.width >= 85 mm and antlers.bb.width <= 95 mm, "antlers about 90 mm wide"
    assert antlers.base.width == 30 mm and antlers.base.height == 12 mm, "antler base 30 x 12"
    assert body.name.w.size == 8 mm, "8 mm letters"
    assert (body.front.cut.bb.width == 3.1 mm and front_legs.notch.cut.bb.width == 3.1 mm
            and antlers.notch.cut.bb.width == 3.1 mm), "slots 3.1 mm wide"
}
