# Request (bathroom): a two-tier rack for bath bombs on the bathroom shelf, 4 mm ply.
# Two side panels 140 mm deep: flat bottom, vertical back 125 mm tall, a 60 mm flat top at
# the back, then a 45 deg slope down to a 65 mm tall front; corners rounded 6 mm; a shallow
# arch 80 mm wide and 15 mm high cut from the bottom to make feet; five bubbles of 4 to
# 10 mm radius engraved on the outside of each panel. Two shelves 80 mm deep with 252 mm
# between the side panels, each with four 45 mm round seats on a 60 mm pitch for the bombs;
# the front shelf's underside 50 mm up, the back shelf's 110 mm up, the back shelf against
# the back edge; each shelf end has two 15 mm tabs through mortises in the side panel.

import "std/joints.aidl"

thickness 4 mm

T = 4 mm
DEPTH = 140 mm
INNER = 252 mm
SHELF_D = 80 mm
LOW_Y = 50 mm
HIGH_Y = 110 mm
SEAT_D = 45 mm
PITCH = 60 mm

# s = 1: the front (low shelf) on -x; s = -1 drawn mirrored, for the other side
def side_panel(s=1) -> solid {
    profile = Polygon([(-70 * s, 0), (70 * s, 0), (70 * s, 125), (10 * s, 125),
                       (-50 * s, 65), (-70 * s, 65)])
    Fillet(profile, 6)
    hole feet {
        arch = Ellipse(center=(0, 0), rx=40, ry=15)
    }
    low = tab_and_slot(part="slot", length=SHELF_D, thickness=T, tabs=2, tab=15, screw=0,
                       cx=-30 * s, cy=LOW_Y + T / 2)
    high = tab_and_slot(part="slot", length=SHELF_D, thickness=T, tabs=2, tab=15, screw=0,
                        cx=30 * s, cy=HIGH_Y + T / 2)
    drawing bubbles {
        b1 = Circle(center=(30 * s, 40), radius=10)
        b2 = Circle(center=(52 * s, 70), radius=7)
        b3 = Circle(center=(25 * s, 80), radius=5)
        b4 = Circle(center=(56 * s, 28), radius=4)
        b5 = Circle(center=(-35 * s, 30), radius=6)
    }
}

def shelf() -> solid {
    board = Rectangle(center=(0, 0), width=INNER + 2 * T, height=SHELF_D)
    right_end = tab_and_slot(part="tab", length=SHELF_D, thickness=T, tabs=2, tab=15,
                             screw=0, cx=INNER / 2 + T, cy=0, rotation=-90 deg)
    left_end = tab_and_slot(part="tab", length=SHELF_D, thickness=T, tabs=2, tab=15,
                            screw=0, cx=-(INNER / 2 + T), cy=0, rotation=90 deg)
    hole seats {
        for i in range(4) {
            c = Circle(center=((i - 1.5) * PITCH, 0), diameter=SEAT_D)
        }
    }
}

assembly bath_bomb_rack {
    left = side_panel(s=-1)
    right = side_panel(s=1)
    low_shelf = shelf()
    high_shelf = shelf()

    left.bb.center == (-90, 80)
    right.bb.center == (90, 80)
    low_shelf.bb.center == (0, -60)
    high_shelf.bb.center == (0, -160)

    # standing: the front is -y; the panels' engraving faces outward
    Place(left, position=(-INNER / 2, 0, 0), face="left", up="up")
    Place(right, position=(INNER / 2, 0, 0), face="right", up="up")
    Place(low_shelf, position=(0, -30, LOW_Y))
    Place(high_shelf, position=(0, 30, HIGH_Y))

    assert right.profile.bb.width == 140 mm, "140 deep"
    assert right.profile.bb.height == 125 mm, "125 tall at the back"
    assert right.feet.arch.rx * 2 == 80 mm and right.feet.arch.ry == 15 mm, "arch 80 x 15"
    assert low_shelf.board.width == 252 mm + 2 * T, "252 between the panels"
    assert low_shelf.board.height == 80 mm, "shelves 80 deep"
    assert len(low_shelf.seats.c) == 4, "four seats"
    assert low_shelf.seats.c[1].center.x - low_shelf.seats.c[0].center.x == 60 mm, "pitch"
    assert low_shelf.seats.c[0].diameter == 45 mm, "45 mm seats"
    # the back shelf's mortises lie within the panel, against the back edge
    assert right.profile.bb.right - right.high.bb.right >= 5 mm, "wood behind the back mortise"
    assert right.high.bb.top <= 125 mm - 5 mm, "wood above the back mortise"
    # the low shelf's front mortise lies under the slope
    assert right.low.bb.left - right.profile.bb.left >= 5 mm, "wood before the front mortise"
    assert distance(right.bubbles, right.high) >= 3 mm and distance(right.bubbles, right.feet) >= 3 mm,
        "bubbles clear of the cuts"
}
