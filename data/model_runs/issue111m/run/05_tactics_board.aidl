# Sport: football tactics board, 3 mm birch ply, in two pieces joined by a sliding
# dovetail: the pitch board 300 wide x 200 tall (10 mm radii on its top corners) with
# four dovetail tails, 10 mm deep, 10 deg, along its whole bottom edge; the counter strip
# 300 x 40 below it (10 mm radii on its bottom corners) with the sockets (0.1 mm
# clearance) and ten 14 mm holes for player counters, 28 mm apart, centred, their
# centres 15 mm above the strip's bottom. Engraved on the board: the touchline, a
# 280 x 180 rectangle centred on it; the halfway line; a 50 mm centre circle and a 2 mm
# centre spot; at each end a penalty area 40 deep x 100 tall and a goal area 15 deep x
# 50 tall on the goal line, a 2 mm penalty spot 24 mm out and a R20 arc about it
# outside the penalty area.

import "std/joints.aidl"

thickness 3 mm

param counters = 10, min = 6, max = 10

assembly tactics {
    solid board {
        body = RoundedRectangle(center=(0, -5), width=300, height=210,
                                corner_radii=[10, 10, 0, 0])
        tails = dovetail(part="tail", length=300 mm, depth=10 mm, tails=4, angle=10 deg,
                         rotation=180 deg, cx=0 mm, cy=-100 mm)
        drawing pitch {
            touch = Rectangle(center=(0, 0), width=280, height=180)
            halfway = Line((0, 90), (0, -90))
            centre = Circle(center=(0, 0), diameter=50)
            spot = Circle(center=(0, 0), diameter=2)
            box_l = Polyline([(-140, 50), (-100, 50), (-100, -50), (-140, -50)])  # the goal line is the touchline
            box_r = Polyline([(140, 50), (100, 50), (100, -50), (140, -50)])
            goal_l = Polyline([(-140, 25), (-125, 25), (-125, -25), (-140, -25)])
            goal_r = Polyline([(140, 25), (125, 25), (125, -25), (140, -25)])
            pen_l = Circle(center=(-116, 0), diameter=2)
            pen_r = Circle(center=(116, 0), diameter=2)
            arc_l = Arc(center=(-116, 0), radius=20, start_angle=-acos(16 / 20),
                        end_angle=acos(16 / 20))
            arc_r = Arc(center=(116, 0), radius=20, start_angle=180 deg - acos(16 / 20),
                        end_angle=180 deg + acos(16 / 20))
        }
    }

    solid strip {
        body = RoundedRectangle(center=(0, -120), width=300, height=40,
                                corner_radii=[0, 0, 10, 10])
        sockets = dovetail(part="socket", length=300 mm, depth=10 mm, tails=4, angle=10 deg,
                           clearance=0.1 mm, rotation=180 deg, cx=0 mm, cy=-100 mm)
        hole counter {
            c = Circle(center=(-126, -125), diameter=14)
        }
        row = LinearPattern(counter, counters, (28, 0))
    }

    assert board.body.width == 300 mm, "board 300 wide"
    assert board.body.bb.top - strip.body.bb.top == 200 mm, "board 200 tall above the joint"
    assert strip.body.width == 300 mm and strip.body.height == 40 mm, "strip 300 x 40"
    assert board.body.bb.bottom == strip.body.bb.top - 10 mm, "tails 10 deep into the strip"
    assert len(strip.row) == 10, "ten counters"
    assert strip.counter.c.diameter == 14 mm, "14 mm counter holes"
    assert strip.row[1].c.center.x - strip.row[0].c.center.x == 28 mm, "counters 28 apart"
    assert (strip.row[0].c.center.x + strip.row[9].c.center.x) / 2 == strip.body.center.x, "counters centred"
    assert strip.row[0].c.center.y - strip.body.bb.bottom == 15 mm, "counters 15 above the bottom"
    assert board.pitch.touch.width == 280 mm and board.pitch.touch.height == 180 mm, "touchline 280 x 180"
    assert board.pitch.touch.center.y == (board.body.bb.top + strip.body.bb.top) / 2, "pitch centred on the board"
    assert board.pitch.centre.diameter == 50 mm, "50 mm centre circle"
    assert board.pitch.box_l.bb.width == 40 mm and board.pitch.box_l.bb.height == 100 mm, "penalty area 40 x 100"
    assert board.pitch.goal_r.bb.width == 15 mm and board.pitch.goal_r.bb.height == 50 mm, "goal area 15 x 50"
    assert board.pitch.pen_l.center.x - board.pitch.touch.bb.left == 24 mm, "penalty spot 24 out"
    assert board.pitch.arc_l.radius == 20 mm, "R20 arc"
    assert abs(board.pitch.arc_l.start.x - board.pitch.box_l.bb.right) < 0.01 mm, "arc meets the penalty area"
}
