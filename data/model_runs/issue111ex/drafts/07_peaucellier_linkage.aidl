# Request: a Peaucellier-Lipkin straight-line linkage for the maths classroom, 3 mm acrylic,
# joined by M4 screws (4.2 mm holes) with washers as spacers. A base 200 x 200 mm (R6)
# with the fixed pivots O and A 35 mm apart on a horizontal line, O 30 mm in from the left
# edge at mid-height. Seven links, each a 12 mm wide round-ended bar with a hole at each
# end: a crank A-C of 35 mm (= OA), two arms O-B and O-D of 100 mm, four rhombus links B-C,
# C-D, D-P, P-B of 40 mm (hole centre to hole centre), each engraved with its name (4 mm).
# Then P runs on a straight line at right angles to OA, (100^2 - 40^2) / (2 x 35) = 120 mm
# from O: engrave that line on the base (y from -75 to 75 mm, O at 0) with 3 mm ticks every
# 10 mm on its left, the arc that C runs on (crank angles -70 to 70 degrees), "O" and "A"
# beside the pivots and "PEAUCELLIER-LIPKIN 1864" (6 mm) 12 mm above the bottom edge.
# Lay the parts out for cutting; in 3D show the linkage with OC at 20 degrees, the links in
# four layers so that each joint's links lie directly on one another.

thickness 3 mm

param r = 35 mm        # O to A, and the crank
param arm = 100 mm
param side = 40 mm
param phi = 20 deg     # the angle of OC shown in 3D
param width = 12 mm
param hole_d = 4.2 mm
param ply = 3 mm
param gap = 5 mm

k = arm * arm - side * side
line_x = k / (2 * r)
# the linkage at phi: O = (0, 0), A = (r, 0)
oc = 2 * r * cos(phi)
op = k / oc
cx = oc * cos(phi)
cy = oc * sin(phi)
px = op * cos(phi)
py = op * sin(phi)
mid = (oc + op) / 2
half = sqrt(side * side - ((op - oc) / 2) ** 2)
bx = mid * cos(phi) - half * sin(phi)
by = mid * sin(phi) + half * cos(phi)
dx = mid * cos(phi) + half * sin(phi)
dy = mid * sin(phi) - half * cos(phi)

def ang(x1, y1, x2, y2) = atan2(y2 - y1, x2 - x1)

def link(c2c=40 mm, name="BC") -> solid {
    bar = Slot(start=(0, 0), end=(c2c, 0), width=width)
    hole pivots {
        a = Circle(center=(0, 0), diameter=hole_d)
        b = Circle(center=(c2c, 0), diameter=hole_d)
    }
    drawing label {
        t = Text(name, position=(c2c / 2, 0), size=4, valign="middle")
    }
}

assembly peaucellier {
    solid base {
        plate = RoundedRectangle(bottom_left=(-30, -100), width=200, height=200, corner_radius=6)
        hole o_pivot { c = Circle(center=(0, 0), diameter=hole_d) }
        hole a_pivot { c = Circle(center=(r, 0), diameter=hole_d) }
        drawing marks {
            path = Line((line_x, -75), (line_x, 75))
            for i in range(15) {
                tick = Line((line_x - 3 mm, -70 mm + i * 10 mm), (line_x, -70 mm + i * 10 mm))
            }
            c_arc = Arc(center=(r, 0), radius=r, start_angle=-70 deg, end_angle=70 deg)
            o_name = Text("O", position=(-8, 0), size=5, anchor="end", valign="middle")
            a_name = Text("A", position=(r, -8), size=5, valign="top")
            title = Text("PEAUCELLIER-LIPKIN 1864", position=(70, -88), size=6)
        }
        Fixed(plate)
    }
    crank = link(c2c=r, name="AC")
    arm_b = link(c2c=arm, name="OB")
    arm_d = link(c2c=arm, name="OD")
    bc = link(c2c=side, name="BC")
    cd = link(c2c=side, name="CD")
    dp = link(c2c=side, name="DP")
    pb = link(c2c=side, name="PB")

    # the sheet: links in a column right of the base
    RightOf(arm_b, base, gap=gap)
    AlignTop(arm_b, base)
    Below(arm_d, arm_b, gap=gap)
    AlignLeft(arm_d, arm_b)
    Below(crank, arm_d, gap=gap)
    AlignLeft(crank, arm_d)
    RightOf(bc, crank, gap=gap)
    AlignTop(bc, crank)
    Below(cd, crank, gap=gap)
    AlignLeft(cd, crank)
    RightOf(dp, cd, gap=gap)
    AlignTop(dp, cd)
    Below(pb, cd, gap=gap)
    AlignLeft(pb, cd)

    # 3D: the base on the table, the links in layers 1 to 4 above it
    Place(base, position=(0, 0, 0))
    Place(crank, position=(r, 0, ply), rotation=(0, 0, ang(r, 0, cx, cy)))
    Place(pb, position=(px, py, ply), rotation=(0, 0, ang(px, py, bx, by)))
    Place(bc, position=(bx, by, 2 * ply), rotation=(0, 0, ang(bx, by, cx, cy)))
    Place(dp, position=(dx, dy, 2 * ply), rotation=(0, 0, ang(dx, dy, px, py)))
    Place(cd, position=(cx, cy, 3 * ply), rotation=(0, 0, ang(cx, cy, dx, dy)))
    Place(arm_b, position=(0, 0, 3 * ply), rotation=(0, 0, ang(0, 0, bx, by)))
    Place(arm_d, position=(0, 0, 4 * ply), rotation=(0, 0, ang(0, 0, dx, dy)))

    # the request's numbers
    assert base.plate.width == 200 mm and base.plate.height == 200 mm, "base 200 x 200"
    assert base.a_pivot.c.center.x - base.o_pivot.c.center.x == 35 mm, "O to A 35"
    assert base.o_pivot.c.center.x - base.plate.bb.left == 30 mm, "O 30 in from the left"
    assert base.o_pivot.c.center.y == base.plate.bb.center_y, "O at mid-height"
    assert crank.pivots.b.center.x - crank.pivots.a.center.x == 35 mm, "crank 35"
    assert arm_b.pivots.b.center.x - arm_b.pivots.a.center.x == 100 mm, "arms 100"
    assert bc.pivots.b.center.x - bc.pivots.a.center.x == 40 mm, "rhombus 40"
    assert bc.bar.width == 12 mm and bc.pivots.a.diameter == 4.2 mm, "12 mm bars, 4.2 mm holes"
    assert abs(line_x - 120 mm) < 0.001 mm, "P's line 120 from O"
    assert base.marks.path.start.y == -75 mm and base.marks.path.end.y == 75 mm, "line -75 to 75"
    assert base.marks.title.position.y - base.plate.bb.bottom == 12 mm, "title 12 up"
    assert len(base.marks.tick) == 15, "ticks every 10 mm"
    # the 3D pose closes: every joint where its links meet
    assert abs(sqrt((cx - r) ** 2 + cy ** 2) - r) < 0.001 mm, "C on the crank circle"
    assert abs(sqrt(bx ** 2 + by ** 2) - arm) < 0.001 mm, "B 100 from O"
    assert abs(sqrt(dx ** 2 + dy ** 2) - arm) < 0.001 mm, "D 100 from O"
    assert abs(sqrt((bx - cx) ** 2 + (by - cy) ** 2) - side) < 0.001 mm, "BC 40"
    assert abs(sqrt((px - dx) ** 2 + (py - dy) ** 2) - side) < 0.001 mm, "DP 40"
    assert abs(px - line_x) < 0.001 mm, "P on its line"
    assert oc >= arm - side, "the pose can be reached"
    assert distance(base.marks.title, base.marks.path) >= 2 mm, "title clear of the line"
}
