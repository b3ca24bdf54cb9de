# Request (parties): the frame of a star pinata for a birthday, 2 mm grey board. Front and back
# are five-pointed stars 400 mm tip to tip (outer radius 200 mm, inner radius 90 mm, tips
# rounded 10 mm), with a 6 mm hanging hole 35 mm below the top tip. The front has a 70 x 70 mm
# trap door in its middle, cut on three sides (hinged at the top) with an 8 mm pull hole 10 mm
# above its bottom edge; the back has a 120 mm round filling hole in its middle. Five spacer
# ribs, 60 x 80 mm (the pinata is 80 mm deep between the stars), one along each arm centred
# 110 mm from the middle, each glued into both stars by two 15 mm tabs at each end.
# The sides are wrapped in card strip by hand, then crepe paper.

import "std/joints.aidl"

thickness 2 mm

param t = 2 mm, min = 1.5 mm, max = 4 mm
param depth = 80 mm, min = 60 mm, max = 120 mm
param rib_r = 110 mm, min = 90 mm, max = 130 mm

def rib_part() -> solid {
    body = Rectangle(center=(0, 0), width=60, height=depth + 2 * t)
    # tabs at both ends: into the front star below, the back star above
    top = tab_and_slot(part="tab", length=60 mm, thickness=t, tabs=2, tab=15 mm, screw=0,
                       cx=0 mm, cy=depth / 2 + t)
    bottom = tab_and_slot(part="tab", length=60 mm, thickness=t, tabs=2, tab=15 mm, screw=0,
                          rotation=180 deg, cx=0 mm, cy=-depth / 2 - t)
}

def star_plate() -> solid {
    star = Star(center=(0, 0), points=5, outer_radius=200, inner_radius=90, tip_radius=10)
    hole hang { c = Circle(center=(0, 165), diameter=6) }
    for i in range(5) {
        slot = tab_and_slot(part="slot", length=60 mm, thickness=t, tabs=2, tab=15 mm, screw=0,
                            rotation=90 deg + i * 72 deg,
                            cx=rib_r * cos(90 deg + i * 72 deg),
                            cy=rib_r * sin(90 deg + i * 72 deg))
    }
}

assembly star_pinata {
    solid front {
        plate = star_plate()
        cut door { u = Polyline([(-35, 20), (-35, -50), (35, -50), (35, 20)]) }
        hole pull { c = Circle(center=(0, -40), diameter=8) }
    }
    solid back {
        plate = star_plate()
        hole fill { c = Circle(center=(0, 0), diameter=120) }
    }

    for i in range(5) {
        rib = rib_part()
        # flat on the sheet: in a row under the front star
        Below(rib, front, gap=10)
        rib.bb.left == front.bb.left + i * 70 mm
        # assembled: standing between the stars along arm i, its face square to the arm
        Place(rib, position=(rib_r * cos(90 deg + i * 72 deg) + sin(90 deg + i * 72 deg) * t / 2,
                             0,
                             250 + rib_r * sin(90 deg + i * 72 deg) - cos(90 deg + i * 72 deg) * t / 2),
              face=(-sin(90 deg + i * 72 deg), 0, cos(90 deg + i * 72 deg)), up="back")
    }

    RightOf(back, front, gap=10)
    AlignTop(back, front)

    Place(front, position=(0, -depth / 2, 250), face="front", up="up")
    Place(back, position=(0, depth / 2, 250), face="back", up="up")

    # the request's numbers
    assert 2 * front.plate.star.outer_radius == 400 mm and front.plate.star.inner_radius == 90 mm
    assert front.plate.star.tip_radius == 10 mm
    assert front.plate.star.center.y + 200 mm - front.plate.hang.c.center.y == 35 mm
    assert front.plate.hang.c.diameter == 6 mm
    assert front.door.u.bb.width == 70 mm and front.door.u.bb.height == 70 mm
    assert front.pull.c.diameter == 8 mm
    assert front.pull.c.center.y - front.door.u.bb.bottom == 10 mm
    assert back.fill.c.diameter == 120 mm
    assert len(rib) == 5
    assert rib[0].body.width == 60 mm and rib[0].body.height - 2 * t == 80 mm
    # the filling hole and the door stay clear of the rib slots
    assert rib_r - 30 mm - back.fill.c.radius >= 10 mm
    assert rib_r - 30 mm - norm((35, 50)) >= 10 mm
}
