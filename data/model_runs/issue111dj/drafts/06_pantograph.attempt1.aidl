# Request: a drawing pantograph that copies a picture at 1:2, 1:3 or 1:4, cut from 3 mm
# acrylic. Four bars 20 mm wide with round ends, pivoting on M4 bolts (4.3 mm holes):
# arm 1 from the fixed pivot O (hole 0) to the elbow J (hole at 300 mm); arm 2 from J
# (hole 0) to the tracer stylus T (4.3 mm hole at 300 mm). Arm 1 has pivot holes at 150,
# 100 and 75 mm from O, arm 2 the same distances from J: for 1:2, 1:3, 1:4 (x / 300).
# The short arm 3 pivots on arm 1's chosen hole and arm 4 on arm 2's; the pencil (8 mm
# holes) joins them: arm 3's pencil holes at 150, 100, 75 mm from its pivot, arm 4's at
# 300 - x = 150, 200, 225 mm. Every option hole has its ratio engraved ("1:2" ...) 12 mm
# past it along the bar. A base plate 60 x 40 mm holds O (4.3 mm, centred) and is screwed
# to the drawing board by two countersunk M4 screws 40 mm apart. "PANTOGRAPH" engraved on
# arm 1 between the 1:2 hole and J.

import "std/fasteners.aidl"

thickness 3 mm

L = 300 mm
opts = [150 mm, 100 mm, 75 mm]       # x for 1:2, 1:3, 1:4
marks = [f"1:{i + 2}" for i in range(3)]

def bar(length=300 mm, ends=[0 mm], holes=[], d=4.3 mm, labels=[]) -> solid {
    body = Slot(center=(length / 2, 0), length=length + 20 mm, width=20)
    hole pivots {
        for i in range(len(ends)) {
            c = Circle(center=(ends[i], 0), diameter=4.3)
        }
    }
    hole options {
        for i in range(len(holes)) {
            c = Circle(center=(holes[i], 0), diameter=d)
        }
    }
    drawing ratio {
        for i in range(len(holes)) {
            t = Text(labels[i], position=(holes[i] + 12 mm, 0), size=3.5, valign="middle")
        }
    }
}

assembly pantograph {
    arm1 = bar(length=L, ends=[0 mm, L], holes=opts, labels=marks)
    arm2 = bar(length=L, ends=[0 mm, L], holes=opts, labels=marks)
    arm3 = bar(length=180 mm, ends=[0 mm], holes=opts, d=8 mm, labels=marks)
    arm4 = bar(length=250 mm, ends=[0 mm], holes=[L - x for x in opts], d=8 mm, labels=marks)

    drawing title {
        w = Text("PANTOGRAPH", position=(0, 0), size=6, valign="middle")
    }
    CutInto(title, arm1)
    AlignCenterY(title, arm1.body)
    title.w.position.x == arm1.body.center.x + 75 mm

    solid base {
        plate = Rectangle(center=(0, 0), width=60, height=40)
        hole pivot {
            c = Circle(center=(0, 0), diameter=4.3)
        }
        screw_l = clearance_hole(size=4, cx=-20, cy=0)
        screw_r = clearance_hole(size=4, cx=20, cy=0)
        Countersink([screw_l, screw_r], diameter=8.5 mm)
    }

    # flat layout
    Below(arm2, arm1, gap=5)
    Below(arm3, arm2, gap=5)
    Below(arm4, arm3, gap=5)
    RightOf(base, arm3, gap=10)
    AlignCenterY(base, arm3)
    AlignLeft(arm2, arm1)
    AlignLeft(arm3, arm1)
    AlignLeft(arm4, arm1)

    # 3D at 1:2: O at the origin, arm 1 at 60 deg, arm 2 at -60 deg, the tracer at (300, 0)
    Place(base, position=(0, 0, 0))
    Place(arm1, position=(0, 0, 3), rotation=(0, 0, 60 deg))
    Place(arm2, position=(L * cos(60 deg), L * sin(60 deg), 6), rotation=(0, 0, -60 deg))
    Place(arm3, position=(150 * cos(60 deg), 150 * sin(60 deg), 6), rotation=(0, 0, -60 deg))
    Place(arm4, position=(L * cos(60 deg) + 150 * cos(60 deg), L * sin(60 deg) - 150 * sin(60 deg), 9),
          rotation=(0, 0, 240 deg))

    # the request's numbers
    for i in range(3) {
        assert opts[i] / L == 1 / (i + 2), "option holes give 1:2, 1:3, 1:4"
        assert arm4.options.c[i].center.x - arm4.pivots.c[0].center.x == L - opts[i],
            "arm 4's pencil holes at 300 - x"
        assert arm1.ratio.t[i].position.x - arm1.options.c[i].center.x == 12 mm,
            "labels 12 mm past their holes"
    }
    assert arm1.pivots.c[1].center.x - arm1.pivots.c[0].center.x == 300 mm, "O to J 300"
    assert arm2.pivots.c[1].center.x - arm2.pivots.c[0].center.x == 300 mm, "J to T 300"
    assert arm3.options.c[0].c.diameter == 8 mm, "pencil holes 8 mm"
    assert base.plate.bb.width == 60 mm and base.plate.bb.height == 40 mm, "base 60 x 40"
    assert base.screw_r.c.center.x - base.screw_l.c.center.x == 40 mm, "base screws 40 apart"
    assert title.bb.left > arm1.options.c[0].center.x and title.bb.right < arm1.pivots.c[1].center.x,
        "title between the 1:2 hole and J"
}
