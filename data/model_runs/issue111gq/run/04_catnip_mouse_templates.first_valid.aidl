# Request: sewing templates for a felt catnip mouse (a cat toy), cut from 3 mm clear acrylic so
# they can be traced round. Three templates, each cut on the cutting line with a 6 mm seam
# allowance outside the stitching line, which is engraved:
# - side (cut 2): stitching line a mouse in profile, 110 mm from the pointed nose to the tail
#   end along a straight belly seam, about 35 mm high, the back a smooth curve; two 4 mm deep
#   V notches in the belly edge 40 mm apart (the stuffing opening between them, "OPEN"), an
#   eye dot, "SIDE - CUT 2" and "6 mm SEAM";
# - base (cut 1): a slim pointed lens 110 mm long and 26 mm wide on the stitching line, a grain
#   line and "BASE - CUT 1";
# - ear (cut 4): a rounded ear 24 mm wide, 18 mm tall on the stitching line, flat at the base,
#   "EAR 4".
# Each has a hanging hole (4 mm; 3 mm on the ear) to keep them on a hook.

thickness 3 mm

seam = 6 mm

def side_line() = Spline([(-55 mm, 0), (55 mm, 0), (48 mm, 16 mm), (25 mm, 32 mm), (-5 mm, 35 mm),
                          (-32 mm, 24 mm)], closed=true, corners=[0, 1])
def base_line() = Spline([(-55 mm, 0), (-25 mm, 9 mm), (15 mm, 13 mm), (45 mm, 8 mm), (55 mm, 0)],
                         closed=true, mirror="x", corners=[0, 4])
def ear_line() = Spline([(-10 mm, 0), (-12 mm, 10 mm), (0, 18 mm), (12 mm, 10 mm), (10 mm, 0)],
                        closed=true, corners=[0, 4])
def notch(x) = Polygon([(x - 2 mm, -seam - 1 mm), (x + 2 mm, -seam - 1 mm), (x, -seam + 4 mm)])

assembly mouse_templates {
    solid side {
        body = Offset(side_line(), seam)
        hole cuts {
            n1 = notch(-20 mm)
            n2 = notch(20 mm)
            hang = Circle(center=(35 mm, 10 mm), diameter=4 mm)
        }
        drawing marks {
            s = side_line()
            eye = Circle(center=(-38 mm, 12 mm), radius=1.5 mm)
            name = Text("SIDE - CUT 2", position=(0, 12 mm), size=4.5)
            sa = Text("6 mm SEAM", position=(0, 22 mm), size=3.5)
            open = Text("OPEN", position=(0, 2 mm), size=3)
        }
    }
    solid base {
        body = Offset(base_line(), seam)
        hole cuts {
            hang = Circle(center=(40 mm, 0), diameter=4 mm)
        }
        drawing marks {
            s = base_line()
            grain = Line((-30 mm, -4 mm), (30 mm, -4 mm))
            name = Text("BASE - CUT 1", position=(0, 2 mm), size=4)
        }
    }
    solid ear {
        body = Offset(ear_line(), seam)
        hole cuts {
            hang = Circle(center=(0, 11 mm), diameter=3 mm)
        }
        drawing marks {
            s = ear_line()
            name = Text("EAR 4", position=(0, 2 mm), size=3)
        }
    }
    Below(base, side, gap=6)
    AlignLeft(base, side)
    RightOf(ear, side, gap=6)
    AlignBottom(ear, side)

    # the request's numbers
    assert side.marks.s.points[1].x - side.marks.s.points[0].x == 110 mm, "110 mm nose to tail"
    assert side.marks.s.bb.height >= 33 mm and side.marks.s.bb.height <= 37 mm, "about 35 mm high"
    assert side.body.bb.width - side.marks.s.bb.width == 2 * 6 mm, "6 mm seam allowance (side)"
    assert base.body.bb.height - base.marks.s.bb.height == 2 * 6 mm, "6 mm seam allowance (base)"
    assert base.marks.s.bb.width == 110 mm and base.marks.s.bb.height <= 27 mm and
        base.marks.s.bb.height >= 25 mm, "base 110 x 26"
    assert ear.marks.s.bb.width >= 23 mm and ear.marks.s.bb.width <= 25 mm and
        ear.marks.s.bb.height == 18 mm, "ear 24 x 18"
    assert side.cuts.n2.points[2].x - side.cuts.n1.points[2].x == 40 mm, "notches 40 mm apart"
    assert side.body.bb.bottom - side.cuts.n1.points[2].y == -4 mm, "notches 4 mm deep"
    assert distance(side.marks.name, side.cuts) >= 2 mm and distance(side.marks.sa, side.cuts) >= 2 mm,
        "side labels clear of the holes"
    assert distance(base.marks.name, base.cuts) >= 2 mm and distance(ear.marks.name, ear.cuts) >= 1 mm,
        "labels clear of the hanging holes"
}
