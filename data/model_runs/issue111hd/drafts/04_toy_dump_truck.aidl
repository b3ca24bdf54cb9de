# Request (toys): "A flat-pack toy dump truck from 4 mm ply whose tipper really tips.
# Two body sides 200 mm long: a chassis rail 25 mm tall whose underside is 15 mm off
# the ground, a cab 60 mm long and 75 mm tall at the front with a 35 x 25 mm window,
# and a lug at the rear for the tipper's 6 mm pivot dowel (hole 10 mm above the rail).
# Axle holes 6.5 mm (6 mm dowel axles) 10 mm above the rail's underside, 125 mm apart,
# the rear one 40 mm from the tail. Two spacers hold the sides 70 mm apart inside,
# glued with a 12 mm tab into a mortise at each end. Four wheels 50 mm across with a
# 6 mm hole (glued on the axle) and an engraved 30 mm hub ring. The tipper: two sides
# 125 mm long at the bottom, 50 mm tall, with the pivot hole 8 mm in and 10 mm up,
# and a floor 105 mm long joined to each side with two 25 mm tabs; the tipper is 68 mm
# wide outside so it swings between the body sides' lugs."

import "std/joints.aidl"

thickness 4 mm

T = 4 mm
inner = 70 mm            # between the body sides
tip_floor_w = inner - 2 mm - 2 * T     # 1 mm clear each side: 68 outside

def body_side(x0=0 mm, y0=0 mm) -> solid {
    # y0: the ground; x0: the tail
    rail = Rectangle(bottom_left=(x0, y0 + 15), width=200, height=25)
    cab = RoundedRectangle(bottom_left=(x0 + 140, y0 + 15), width=60, height=75,
                           corner_radii=[12, 6, 0, 0])
    lug = Rectangle(bottom_left=(x0, y0 + 40), width=16, height=18)
    hole window { w = Rectangle(center=(x0 + 168, y0 + 66), width=35, height=25) }
    hole axles {
        rear = Circle(center=(x0 + 40, y0 + 25), diameter=6.5)
        front = Circle(center=(x0 + 165, y0 + 25), diameter=6.5)
    }
    hole pivot { p = Circle(center=(x0 + 8, y0 + 50), diameter=6.5) }
    # FIX after the first valid program: the spacers' tops (were 37.5) now level with the
    # rail's top (40), so the lowered tipper rests on them instead of sagging 2.5 mm
    m1 = tab_and_slot(part="slot", length=20 mm, thickness=4 mm, tabs=1, tab=12 mm, screw=0,
                      rotation=90 deg, cx=x0 + 80 mm, cy=y0 + 30 mm)
    m2 = tab_and_slot(part="slot", length=20 mm, thickness=4 mm, tabs=1, tab=12 mm, screw=0,
                      rotation=90 deg, cx=x0 + 125 mm, cy=y0 + 30 mm)
    drawing grille {
        for i in range(4) {
            g = Line((x0 + 188, y0 + 22 + i * 5), (x0 + 198, y0 + 22 + i * 5))
        }
    }
}

def spacer(x0=0 mm, y0=0 mm) -> solid {
    # x0, y0: its middle; 70 between the sides plus a 4 mm tab each end
    web = Rectangle(center=(x0, y0), width=78, height=20)
    left_tab = tab_and_slot(part="tab", length=20 mm, thickness=4 mm, tabs=1, tab=12 mm,
                            screw=0, rotation=90 deg, cx=x0 - 39 mm, cy=y0)
    right_tab = tab_and_slot(part="tab", length=20 mm, thickness=4 mm, tabs=1, tab=12 mm,
                             screw=0, rotation=-90 deg, cx=x0 + 39 mm, cy=y0)
}

def wheel(x0=0 mm, y0=0 mm) -> solid {
    tyre = Circle(center=(x0, y0), diameter=50)
    hole axle { a = Circle(center=(x0, y0), diameter=6) }
    drawing hub { r = Circle(center=(x0, y0), diameter=30) }
}

def tipper_side(x0=0 mm, y0=0 mm) -> solid {
    # x0, y0: bottom-rear corner
    plate = Polygon([(x0, y0), (x0 + 125, y0), (x0 + 130, y0 + 50), (x0 - 10, y0 + 50),
                     (x0, y0 + 22)])
    hole pivot { p = Circle(center=(x0 + 8, y0 + 10), diameter=6.5) }
    floor_slots = tab_and_slot(part="slot", length=105 mm, thickness=4 mm, tabs=2, tab=25 mm,
                               screw=0, cx=x0 + 70 mm, cy=y0 + 6 mm)
}

def tipper_floor(x0=0 mm, y0=0 mm) -> solid {
    # x0, y0: its middle; along the truck 105, across 60 plus 4 mm tabs each side
    deck = Rectangle(center=(x0, y0), width=105, height=60 + 8)
    top_tabs = tab_and_slot(part="tab", length=105 mm, thickness=4 mm, tabs=2, tab=25 mm,
                            screw=0, cx=x0, cy=y0 + 34 mm)
    bottom_tabs = tab_and_slot(part="tab", length=105 mm, thickness=4 mm, tabs=2, tab=25 mm,
                               screw=0, rotation=180 deg, cx=x0, cy=y0 - 34 mm)
}

assembly truck {
    side_a = body_side(x0=0 mm, y0=0 mm)
    side_b = body_side(x0=0 mm, y0=100 mm)
    spacer_a = spacer(x0=250 mm, y0=20 mm)
    spacer_b = spacer(x0=250 mm, y0=50 mm)
    for i in range(4) {
        w = wheel(x0=230 mm + i * 55 mm, y0=110 mm)
    }
    tip_a = tipper_side(x0=20 mm, y0=210 mm)
    tip_b = tipper_side(x0=170 mm, y0=210 mm)
    floor = tipper_floor(x0=370 mm, y0=40 mm)

    assert side_a.rail.bb.width == 200 mm and side_a.rail.bb.height == 25 mm, "body 200 long, rail 25"
    assert side_a.rail.bb.bottom - 15 mm == 0 mm, "rail 15 off the ground"
    assert side_a.cab.bb.width == 60 mm and side_a.cab.bb.height == 75 mm, "cab 60 x 75"
    assert side_a.axles.front.center.x - side_a.axles.rear.center.x == 125 mm, "axles 125 apart"
    assert side_a.axles.rear.center.x - side_a.rail.bb.left == 40 mm, "rear axle 40 from the tail"
    assert side_a.axles.rear.center.y - side_a.rail.bb.bottom == 10 mm, "axles 10 above the rail's underside"
    assert side_a.pivot.p.center.y - side_a.rail.bb.top == 10 mm, "pivot 10 above the rail"
    assert spacer_a.web.bb.width - 2 * T == 70 mm, "sides 70 apart inside"
    assert len(w) == 4 and w[0].tyre.diameter == 50 mm and w[0].hub.r.diameter == 30 mm, "4 wheels 50, hub 30"
    assert tip_a.plate.bb.height == 50 mm, "tipper 50 tall"
    assert tip_a.pivot.p.center.x - tip_a.plate.points[0].x == 8 mm and tip_a.pivot.p.center.y - tip_a.plate.points[0].y == 10 mm, "pivot 8 in, 10 up"
    assert floor.deck.bb.width == 105 mm, "tipper floor 105 long"
    assert floor.deck.bb.height == 68 mm, "tipper 68 wide outside"
    assert side_a.m1.slot[0].bb.center_y + spacer_a.web.bb.height / 2 == side_a.rail.bb.top, "FIX: the tipper rests on the spacers"
    assert 68 mm < inner, "the tipper swings between the lugs"
}
