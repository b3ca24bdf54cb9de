# Request (camping): a flat-pack twig stove from 1.5 mm stainless steel: four walls, each
# 150 x 100, that slot together as a "#" (cross-halvings 50 mm deep, slots 1.7 mm wide,
# their centres 20 mm in from each end, so the fire box is 110 x 110 between them):
# - front wall: slots from the top, a fuel door 50 mm wide at the bottom middle, straight
#   sides 25 mm tall under a round top (50 mm across, so 50 mm tall in all);
# - back wall: slots from the top, eight 8 mm air holes in two rows of four (20 mm pitch),
#   the lower row 15 mm above the bottom edge, centred;
# - two side walls: slots from the bottom, three 10 mm air holes 20 mm above the bottom
#   edge at -30, 0 and 30 mm, and three 15 x 8 mm smoke notches in the top edge at the same
#   x (the pot sits on the top edges).

import "std/joints.aidl"

thickness 1.5 mm

w = 150 mm
h = 100 mm
t = 1.5 mm
fit = 0.2 mm
slot_x = w / 2 - 20 mm

def slotted_top() -> solid {
    body = Rectangle(center=(0, 0), width=w, height=h)
    a = cross_halving(depth=h / 2, thickness=t, clearance=fit, cx=-slot_x, cy=h / 2)
    b = cross_halving(depth=h / 2, thickness=t, clearance=fit, cx=slot_x, cy=h / 2)
}

def side_wall() -> solid {
    body = Rectangle(center=(0, 0), width=w, height=h)
    a = cross_halving(depth=h / 2, thickness=t, clearance=fit, rotation=180, cx=-slot_x, cy=-h / 2)
    b = cross_halving(depth=h / 2, thickness=t, clearance=fit, rotation=180, cx=slot_x, cy=-h / 2)
    hole air {
        for i in range(3) {
            c = Circle(center=(-30 + 30 * i, -h / 2 + 20), diameter=10)
        }
    }
    hole smoke {
        for i in range(3) {
            n = Rectangle(corner=(-30 + 30 * i - 7.5, h / 2 - 8), opposite=(-30 + 30 * i + 7.5, h / 2))
            o = Rectangle(corner=(-30 + 30 * i - 7.5, h / 2), opposite=(-30 + 30 * i + 7.5, h / 2 + 1),
                          overrun=true)
        }
    }
}

assembly twig_stove {
    solid front {
        wall = slotted_top()
        hole door {
            lower = Rectangle(corner=(-25, -h / 2), opposite=(25, -h / 2 + 25))
            arch = Circle(center=(0, -h / 2 + 25), diameter=50)
            lip = Rectangle(corner=(-25, -h / 2 - 1), opposite=(25, -h / 2), overrun=true)
        }
    }

    solid back {
        wall = slotted_top()
        hole vent { c = Circle(center=(-30, -h / 2 + 15), diameter=8) }
        vents = GridPattern(vent, 2, 4, (20, 20))
    }

    left = side_wall()
    right = side_wall()

    RightOf(back, front, gap=5)
    AlignBottom(back, front)
    Below(left, front, gap=5)
    AlignLeft(left, front)
    RightOf(right, left, gap=5)
    AlignBottom(right, left)

    assert front.wall.body.bb.width == 150 mm and front.wall.body.bb.height == 100 mm, "150 x 100 walls"
    assert front.wall.a.depth + left.a.depth == 100 mm, "the halvings meet"
    assert abs(front.wall.b.cut.bb.center_x - front.wall.a.cut.bb.center_x - 110 mm) < 0.001 mm, "110 mm between the slots"
    assert abs(left.b.cut.bb.center_x - left.a.cut.bb.center_x - 110 mm) < 0.001 mm, "110 mm between the slots"
    assert front.door.bb.width == 50 mm and front.door.bb.height == 50 mm, "door 50 x 50"
    assert len(back.vents) == 8, "eight air holes"
}
