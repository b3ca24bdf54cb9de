# Shape-sorter lid (toys): the top panel of a wooden shape-sorter box, 140 x 140 mm outside,
# 4 mm plywood, finger joints (12 mm fingers) on all four edges. Five openings, each 1.5 mm
# larger across than its block (0.75 mm all round): a 32 mm round block, a 28 mm square block,
# a triangle block of 34 mm sides (pointing up), a 5-point star block (40 mm across the tips,
# inner radius 9 mm) and a heart block (34 mm wide, 30 mm tall). Top row: circle, square,
# triangle with centres 40 mm apart, 30 mm above the middle; bottom row: star and heart,
# centres 25 mm below the middle and 20 mm left and right of it.
units mm
thickness 4 mm

import "std/joints.aidl"

param play = 0.75 mm, min = 0.3 mm, max = 1.5 mm

solid lid {
    panel = finger_panel(width=140, height=140, thickness=4 mm, finger=12 mm)

    hole round { c = Circle(center=(-40, 30), diameter=32 + 2 * play) }
    hole square { r = Rectangle(center=(0, 30), width=28 + 2 * play, height=28 + 2 * play) }
    hole tri { t = Offset(RegularPolygon(center=(40, 30), side=34, sides=3, rotation=90 deg), play, join="miter") }
    hole star { s = Star(center=(-20, -25), points=5, outer_radius=20 + play, inner_radius=9 + play) }
    hole heart {
        h = Hull(Circle(center=(12, -19), radius=9 + play), Circle(center=(28, -19), radius=9 + play),
                 Point(20, -40 - play))
    }

    assert panel.outline.width == 140 mm and panel.outline.height == 140 mm, "lid 140 x 140"
    assert round.c.diameter == 33.5 mm, "32 mm block + 1.5"
    assert square.r.width == 29.5 mm, "28 mm block + 1.5"
    assert star.s.outer_radius == 20.75 mm, "star 40 across the tips + 1.5"
    assert heart.bb.width == 35.5 mm and heart.bb.height == 31.5 mm, "heart 34 x 30 + 1.5"
    assert round.c.center.y == 30 mm and square.r.center.y == 30 mm, "top row 30 above the middle"
    assert square.r.center.x - round.c.center.x == 40 mm, "centres 40 apart"
    assert star.s.center.y == -25 mm and abs(star.s.center.x) == 20 mm, "star 25 below, 20 left"
    assert heart.bb.center_y == -25 mm and heart.bb.center_x == 20 mm, "heart 25 below, 20 right"
}
