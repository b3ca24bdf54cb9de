# Request (pets): a climbing frame for my hermit crabs' tank, 4 mm poplar plywood (sealed).
# Two panels 200 mm wide, 160 mm tall at the middle of an arched top and 140 mm at the ends,
# cross-halved into a plus shape (each slot 80 mm deep, 0.2 mm clearance). Each panel has two
# hide arches at its foot, 30 mm wide and 40 mm tall, centred 50 mm either side of the middle,
# and climbing holds: a staggered grid of 12 mm holes, 5 rows x 4 a side, 18 mm across and
# 18 mm up. The panels stand in a round base 220 mm across with four 12 mm tabs each (glued),
# and the base is engraved with the crab's name, SHELLDON, along its rim.

import "std/joints.aidl"

thickness 4 mm

def crab_panel(from_top=true) -> solid {
    # outline: bottom at the tab tips (y = -4), arched top 160 mm over the tab roots
    bottom = Line((-100, -4), (100, -4))
    right = Line((100, -4), (100, 140))
    top = Arc(start=(100, 140), through=(0, 160), end=(-100, 140))
    left = Line((-100, 140), (-100, -4))
    axis = Line((0, -10), (0, 170), construction=true)

    feet = tab_and_slot(part="tab", length=200 mm, thickness=4 mm, tabs=4, tab=12 mm,
                        screw=0, rotation=180 deg, cx=0 mm, cy=-4 mm)
    if from_top {
        halving = cross_halving(depth=80 mm, thickness=4 mm, clearance=0.2 mm,
                                cx=0 mm, cy=160 mm)
    } else {
        halving = cross_halving(depth=80 mm, thickness=4 mm, clearance=0.2 mm,
                                rotation=180 deg, cx=0 mm, cy=0 mm)
    }
    hole arch_l {
        r = Rectangle(center=(-50, 10), width=30, height=30)
        c = Circle(center=(-50, 25), diameter=30)
    }
    arch_r = Mirrored(arch_l, axis)
    hole holds_l {
        c = Circle(center=(-84, 56), diameter=12)
        g = GridPattern(c, 5, 4, (18, 18), stagger=true)
    }
    holds_r = Mirrored(holds_l, axis)
}

assembly crab_climber {
    a = crab_panel(from_top=true)
    b = crab_panel(from_top=false)

    solid base {
        disc = Circle(center=(0, 0), diameter=220)
        along_x = tab_and_slot(part="slot", length=200 mm, thickness=4 mm, tabs=4, tab=12 mm,
                               screw=0, cx=0 mm, cy=0 mm)
        along_y = tab_and_slot(part="slot", length=200 mm, thickness=4 mm, tabs=4, tab=12 mm,
                               screw=0, rotation=90 deg, cx=0 mm, cy=0 mm)
        drawing name {
            rim = Circle(center=(0, 0), radius=95, construction=true)
            t = Text("SHELLDON", along=rim, angle=-45 deg, flip=true, size=8)
        }
        assert distance(name, along_x) >= 3 mm and distance(name, along_y) >= 3 mm,
            "name clear of the mortises"
        assert disc.diameter == 220 mm, "base 220 across"
    }

    assert a.halving.depth + b.halving.depth == 160 mm, "halvings meet: 80 + 80"
    assert len(a.holds_l.g) == 20, "5 rows x 4 holds a side"
    assert a.arch_l.c.diameter == 30 mm, "arches 30 wide"
    assert a.arch_l.c.center.x - a.axis.start.x == -50 mm, "arches 50 from the middle"

    RightOf(b, a, gap=10)
    AlignBottom(b, a)
    RightOf(base, b, gap=10)
    AlignBottom(base, b)
}
