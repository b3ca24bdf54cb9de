# Request: a wiring-harness jig board for the loom of my small robot, 6 mm ply, 300 x 200 mm
# with R5 corners. The loom: a trunk from connector J1 at (30, 100) (from the board's
# bottom-left corner) to a breakout at (150, 100); from there branch J2 goes to (190, 160)
# then straight to (270, 160), J3 straight to (270, 100), J4 to (190, 40) then to (270, 40).
# Along every leg, pairs of 6 mm holes for dowel pegs, 6 mm either side of the route (so a
# bundle up to 6 mm passes between), about every 20 mm (no pegs at the ends of a leg). The
# route engraved as a centre line, the connector names (6 mm) engraved just beyond each end,
# each branch's length from the breakout engraved (5 mm) above its last leg, "ROBOT LOOM"
# engraved (6 mm) centred 12 mm above the bottom edge. Four M5 holes 10 mm in from the
# corners, countersunk 10 mm, to screw it to the bench.

import "std/fasteners.aidl"

thickness 6 mm

param peg_d = 6 mm
param offset = 6 mm
param pitch = 20 mm

# the legs: [x1, y1, x2, y2] from the board's bottom-left corner
legs = [[30, 100, 150, 100], [150, 100, 190, 160], [190, 160, 270, 160],
        [150, 100, 270, 100], [150, 100, 190, 40], [190, 40, 270, 40]]

def leg_len(s) = sqrt((s[2] - s[0]) ** 2 + (s[3] - s[1]) ** 2)
def n_of(s) = round(leg_len(s) / (pitch / 1 mm))
# a point t along leg s, moved `side` across it (left of its direction: +)
def px(s, t, side) = s[0] + (s[2] - s[0]) * t - side * (s[3] - s[1]) / leg_len(s)
def py(s, t, side) = s[1] + (s[3] - s[1]) * t + side * (s[2] - s[0]) / leg_len(s)

branch_len = [leg_len(legs[1]) + leg_len(legs[2]), leg_len(legs[3]),
              leg_len(legs[4]) + leg_len(legs[5])]

solid board {
    plate = RoundedRectangle(bottom_left=(0, 0), width=300, height=200, corner_radius=5)
    Fixed(plate)

    hole pegs {
        for i in range(len(legs)) {
            for k in range(1, n_of(legs[i])) {
                a = Circle(center=(px(legs[i], k / n_of(legs[i]), offset),
                                   py(legs[i], k / n_of(legs[i]), offset)), diameter=peg_d)
                b = Circle(center=(px(legs[i], k / n_of(legs[i]), -offset),
                                   py(legs[i], k / n_of(legs[i]), -offset)), diameter=peg_d)
            }
        }
    }

    mount = clearance_hole(size=5)
    corners = CornerPattern(mount, plate, inset=10)
    Countersink(corners, diameter=10)

    drawing route {
        trunk = Line((30, 100), (150, 100))
        j2 = Polyline([(150, 100), (190, 160), (270, 160)])
        j3 = Line((150, 100), (270, 100))
        j4 = Polyline([(150, 100), (190, 40), (270, 40)])
        n1 = Text("J1", position=(22, 100), size=6, anchor="end", valign="middle")
        n2 = Text("J2", position=(278, 160), size=6, anchor="start", valign="middle")
        n3 = Text("J3", position=(278, 100), size=6, anchor="start", valign="middle")
        n4 = Text("J4", position=(278, 40), size=6, anchor="start", valign="middle")
        l2 = Text(f"{branch_len[0]:.0f} mm", position=(230, 171), size=5)
        l3 = Text(f"{branch_len[1]:.0f} mm", position=(230, 111), size=5)
        l4 = Text(f"{branch_len[2]:.0f} mm", position=(230, 51), size=5)
        title = Text("ROBOT LOOM", position=(150, 12), size=6)
    }

    # the request's numbers
    assert plate.width == 300 mm and plate.height == 200 mm, "board 300 x 200"
    assert leg_len(legs[0]) == 120 mm, "trunk 120 long"
    assert pegs.a[0][0].diameter == 6 mm, "6 mm peg holes"
    assert distance(pegs.a[0][0].center, pegs.b[0][0].center) == 12 mm, "pegs 6 mm either side"
    assert pegs.a[0][1].center.x - pegs.a[0][0].center.x == 20 mm, "pegs every 20 mm on the trunk"
    assert corners[0].c.center.x - plate.bb.left == 10 mm, "mount holes 10 mm in"
    assert corners[0].c.diameter > 5 mm, "M5 clearance"
    assert route.title.position.y - plate.bb.bottom == 12 mm, "title 12 mm up"
    # pegs of neighbouring legs must not run into each other near the breakout
    assert distance(pegs.b[1][0], pegs.a[3][0]) >= 1.5 mm, "J2 and J3 pegs apart"
    assert distance(pegs.a[4][0], pegs.b[3][0]) >= 1.5 mm, "J4 and J3 pegs apart"
    assert distance(route.n2, corners[2]) >= 2 mm, "J2 label clear of the screw"
}
