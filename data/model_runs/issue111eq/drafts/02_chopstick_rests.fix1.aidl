# Request: a pair of fish-shaped chopstick rests for the dinner table, from 4 mm cherry
# plywood. Each fish stands on its flat belly: 70 mm long nose to tail, 24 mm tall, the
# body an oval 54 x 28 mm with its bottom 4 mm cut off flat, a forked tail. The
# chopsticks lie in a round dip of R6 in its back, the dip's bottom 19 mm above the
# belly, its centre 2 mm behind the body's middle. An eye (a 4 mm engraved dot) and a gill
# line are engraved on one face. So it cannot tip over, a foot 40 mm long and 10 mm tall
# with round ends crosses under the belly's middle, cross-halved: a 5 mm slot up into the
# fish, a 5 mm slot down into the foot. Two fish, two feet: four parts.

import "std/joints.aidl"

units mm
t = 4 mm
thickness t
kerf 0.1 mm

def fish() -> solid {
    oval = Ellipse(center=(0, 10), rx=27, ry=14, construction=true)
    cutoff = Rectangle(bottom_left=(-30, 0), width=60, height=30, construction=true)
    body = Intersect(oval, cutoff)
    tail = Polygon([(18, 11), (43, 22), (37, 11), (43, 1)])
    # FIX after the first valid program: "behind" the middle is toward the tail (+x);
    # the first valid program put the dip 2 mm toward the head, and its assert had the same sign
    hole dip {
        c = Circle(center=(2, 25), radius=6)
    }
    belly_notch = cross_halving(depth=5 mm, thickness=4 mm, rotation=180 deg, cx=0 mm, cy=0 mm)
    drawing face {
        eye = Circle(center=(-17, 14), radius=2, fill=true)
        gill = Arc(center=(-24, 10), radius=12, start_angle=-35 deg, end_angle=35 deg)
    }
}

def foot() -> solid {
    bar = Slot(center=(0, 5), length=40, width=10)
    notch = cross_halving(depth=5 mm, thickness=4 mm, cx=0 mm, cy=10 mm)
}

assembly chopstick_rests {
    fish_a = fish()
    fish_b = fish()
    foot_a = foot()
    foot_b = foot()
    RightOf(fish_b, fish_a, gap=6)
    AlignBottom(fish_b, fish_a)
    Below(foot_a, fish_a, gap=6)
    AlignLeft(foot_a, fish_a)
    RightOf(foot_b, foot_a, gap=6)
    AlignBottom(foot_b, foot_a)

    assert fish_a.tail.bb.right - fish_a.body.bb.left == 70 mm, "70 mm nose to tail"
    assert fish_a.body.bb.height == 24 mm, "24 mm tall"
    assert fish_a.oval.rx * 2 == 54 mm and fish_a.oval.ry * 2 == 28 mm, "oval 54 x 28"
    assert fish_a.dip.c.radius == 6 mm, "dip R6"
    assert fish_a.dip.c.center.y - fish_a.dip.c.radius - fish_a.body.bb.bottom == 19 mm,
        "dip bottom 19 mm above the belly"
    assert fish_a.dip.c.center.x - fish_a.oval.center.x == 2 mm, "dip 2 mm behind the middle (toward the tail)"
    assert foot_a.bar.length == 40 mm and foot_a.bar.width == 10 mm, "foot 40 x 10"
    assert fish_a.belly_notch.depth + foot_a.notch.depth == 10 mm, "halvings add up to the foot's height"
    assert distance(fish_a.face.eye, fish_a.dip) >= 3 mm, "eye clear of the dip"

    # 3D: each fish stands upright facing the front, its foot crosswise under its middle
    Place(fish_a, position=(0, 0, 0), face="front", up="up")
    Place(foot_a, position=(-t / 2, -t / 2, 0), face="right", up="up")
    Place(fish_b, position=(0, 60, 0), face="front", up="up")
    Place(foot_b, position=(-t / 2, 60 - t / 2, 0), face="right", up="up")
}
