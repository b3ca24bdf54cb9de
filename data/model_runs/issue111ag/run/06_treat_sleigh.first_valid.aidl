# Request (holidays): a Christmas treat sleigh for the table, 3 mm ply, glued.
# - two sides 222 mm long, 125 mm tall at the back: a straight runner 170 mm long along
#   the bottom that sweeps up at the front into a curl, a low seat line about 58 mm high
#   and a tall back; a runner window 8 mm wide from 35 to 155 mm along, its centre line
#   12 mm up, so the runner reads as a separate bar;
# - a floor 150 mm long (15 to 165 mm along the sides), 25 mm up (its middle), 90 mm wide
#   between the sides, 2 tabs 20 mm wide into each side;
# - a back rest 60 mm tall standing on the floor 24 mm from the sides' back edge (its
#   middle), 2 tabs 15 mm wide into each side, a 5-point star cut through (12 mm outer
#   radius, 5 mm inner), "NOEL" engraved as filled serif letters 12 mm tall under it;
# - joints 0.1 mm loose.

import "std/joints.aidl"

units mm
thickness 3 mm

T = 3 mm
fit = 0.1 mm
inner_w = 90 mm
floor_y = 25 mm
floor_x0 = 15 mm
floor_len = 150 mm
rest_x = 24 mm
rest_h = 60 mm
rest_cy = floor_y + T / 2 + rest_h / 2

def side_panel() -> solid {
    outline = Spline([(0, 0), (170, 0), (200, 8), (218, 30), (222, 55), (210, 75),
                      (192, 74), (185, 62), (170, 58), (110, 58), (55, 72), (25, 110),
                      (8, 125), (0, 115)], closed=true, corners=[0, 1, 13])
    Fixed(outline)
    hole window {
        s = Slot(start=(35, 12), end=(155, 12), width=8)
    }
    floor_slots = tab_and_slot(part="slot", length=floor_len, thickness=T, tabs=2, tab=20 mm,
                               screw=0, clearance=fit, rotation=0 deg,
                               cx=floor_x0 + floor_len / 2, cy=floor_y)
    rest_slots = tab_and_slot(part="slot", length=rest_h, thickness=T, tabs=2, tab=15 mm,
                              screw=0, clearance=fit, rotation=90 deg, cx=rest_x, cy=rest_cy)
}

assembly sleigh {
    left = side_panel()
    right = side_panel()

    solid floor {
        body = Rectangle(center=(0, 0), width=floor_len, height=inner_w + 2 * T)
        Fixed(body)
        to_left = tab_and_slot(part="tab", length=floor_len, thickness=T, tabs=2, tab=20 mm,
                               screw=0, rotation=0 deg, cx=0, cy=inner_w / 2 + T)
        to_right = tab_and_slot(part="tab", length=floor_len, thickness=T, tabs=2, tab=20 mm,
                                screw=0, rotation=180 deg, cx=0, cy=-(inner_w / 2 + T))
    }

    solid rest {
        body = Rectangle(center=(0, 0), width=inner_w + 2 * T, height=rest_h)
        Fixed(body)
        to_left = tab_and_slot(part="tab", length=rest_h, thickness=T, tabs=2, tab=15 mm,
                               screw=0, rotation=90 deg, cx=-(inner_w / 2 + T), cy=0)
        to_right = tab_and_slot(part="tab", length=rest_h, thickness=T, tabs=2, tab=15 mm,
                                screw=0, rotation=-90 deg, cx=inner_w / 2 + T, cy=0)
        hole star {
            s = Star(center=(0, 12), points=5, outer_radius=12, inner_radius=5)
        }
        drawing word {
            t = Text("NOEL", position=(0, -15), size=12, font="serif", valign="middle",
                     fill=true)
        }
    }

    Fixed(left)
    RightOf(right, left, gap=10)
    AlignBottom(right, left)
    Above(floor, left, gap=10)
    AlignLeft(floor, left)
    RightOf(rest, floor, gap=10)
    AlignBottom(rest, floor)

    assert left.outline.points[4].x == 222 mm, "sides 222 long"
    assert left.outline.points[12].y == 125 mm, "125 tall at the back"
    assert left.outline.points[1].x - left.outline.points[0].x == 170 mm, "170 mm straight runner"
    assert left.outline.bb.bottom > -0.01 mm, "the runner stays flat: nothing dips below it"
    assert left.window.s.width == 8 mm, "runner window 8 wide"
    assert floor.body.bb.width == 150 mm, "floor 150 long"
    assert floor.body.bb.height - 2 * T == 90 mm, "90 mm between the sides"
    assert rest.body.bb.height == 60 mm, "back rest 60 tall"
    assert rest.star.s.outer_radius == 12 mm, "star 12 mm"
    assert rest.word.bb.top < rest.star.bb.bottom, "NOEL under the star"
    assert rest.word.bb.bottom > rest.body.bb.bottom, "NOEL on the rest"
    assert left.rest_slots.bb.top < 110 mm, "the back rest's slots stay inside the tall back"
}
