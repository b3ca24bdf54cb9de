# Request: a tabletop mini football (foosball) game from 3 mm ply.
# - An open-top finger-jointed tray 400 x 250 x 70 mm outside.
# - Four 6 mm dowel rods across the width, 50 mm above the bottom, at x = -150, -50, 50 and
#   150 mm: a 7 mm hole for each in the front and in the back wall.
# - A goal in each end wall: an 80 x 30 mm opening, 8 mm above the bottom, centred.
# - The floor engraved as a pitch: a 380 x 230 outline, halfway line, 60 mm centre circle,
#   centre spot, and a 40 x 100 mm penalty box at each end.
# - Eight players (two on each rod, 50 mm either side of the centre line): a flat figure
#   with a head (16 mm), a 20 x 36 mm body and legs, a 6.2 mm hole for the rod (a snug fit,
#   glued), the team letter "A" or "B" engraved on the chest. Goalie A at x = -150, forwards
#   B at -50, forwards A at 50, goalie B at 150. The feet clear the floor.

import "std/joints.aidl"

thickness 3 mm

param t = 3 mm, min = 2.5 mm, max = 4 mm
rod_z = 50 mm
rod_x = [-150 mm, -50 mm, 50 mm, 150 mm]
teams = ["A", "B", "A", "B"]
player_y = [-50 mm, 50 mm]

def player(team="A") -> solid {
    head = Circle(center=(0, 16), radius=8)
    neck = Rectangle(center=(0, 7), width=8, height=4)
    body = RoundedRectangle(center=(0, -12), width=20, height=36, corner_radius=4)
    legs = Rectangle(center=(0, -37), width=14, height=14)
    hole rod { c = Circle(center=(0, 0), diameter=6.2) }
    drawing badge { letter = Text(team, position=(0, -14), size=8, valign="middle") }
    Fixed(head)
    Fixed(neck)
    Fixed(body)
    Fixed(legs)
    Fixed(rod)
    Fixed(badge)
}

assembly game {
    box = finger_box(length=400 mm, depth=250 mm, height=70 mm, thickness=t, finger=12 mm,
                     closed=false)

    hole rods_front {
        for x in rod_x { h = Circle(center=(x, 0), diameter=7) }
    }
    rods_front.h[0].center.y == box.front.bb.bottom + rod_z
    rods_front.h[0].center.x == box.front.bb.center_x + rod_x[0]
    CutInto(rods_front, box.front)

    hole rods_back {
        for x in rod_x { h = Circle(center=(x, 0), diameter=7) }
    }
    rods_back.h[0].center.y == box.back.bb.bottom + rod_z
    rods_back.h[0].center.x == box.back.bb.center_x + rod_x[0]
    CutInto(rods_back, box.back)

    # the sides lie on the sheet with their top edge outward: the left's bottom edge is its
    # right side, the right's bottom edge its left side
    hole goal_left { g = Rectangle(center=(0, 0), width=30, height=80) }
    goal_left.bb.right == box.left.bb.right - 8 mm
    AlignCenterY(goal_left, box.left)
    CutInto(goal_left, box.left)

    hole goal_right { g = Rectangle(center=(0, 0), width=30, height=80) }
    goal_right.bb.left == box.right.bb.left + 8 mm
    AlignCenterY(goal_right, box.right)
    CutInto(goal_right, box.right)

    drawing pitch {
        outline = Rectangle(center=(0, 0), width=380, height=230)
        halfway = Line((0, -115), (0, 115))
        circle = Circle(center=(0, 0), diameter=60)
        spot = Circle(center=(0, 0), radius=1.5, fill=true)
        box_l = Rectangle(center=(-170, 0), width=40, height=100)
        box_r = Rectangle(center=(170, 0), width=40, height=100)
        Rigid(outline, halfway, circle, spot, box_l, box_r)
    }
    CenterInside(pitch, box.bottom)
    CutInto(pitch, box.bottom)

    for i in range(8) {
        r = i // 2
        p = player(team=teams[r])
        p.bb.top == box.bb.bottom - 10 mm
        p.bb.left == box.bb.left + i * 30 mm
        Place(p, position=(rod_x[r], player_y[i % 2] + t / 2, rod_z), face="front", up="up")
    }

    assert len(p) == 8
    assert len(rods_front.h) == 4 and len(rods_back.h) == 4
    assert rods_front.h[0].center.y - box.front.bb.bottom == 50 mm
    assert rods_front.h[1].center.x - rods_front.h[0].center.x == 100 mm
    assert goal_left.g.width == 30 mm and goal_left.g.height == 80 mm
    assert box.bottom.bb.width == 400 mm and box.bottom.bb.height == 250 mm
    assert p[0].head.radius == 8 mm and p[0].rod.c.diameter == 6.2 mm
    assert rod_z + p[0].legs.bb.bottom > t, "the feet clear the floor"
}
