# Request (music): for a guitar build, a humbucker mounting ring and the routing template for
# its cavity, cut together.
# - Ring, 3 mm black acrylic: 92 x 46 mm, corners r8; an opening 71 x 39.5 mm (r3) for a
#   70 x 38.5 mm humbucker; four 3 mm holes for #4 wood screws at (+-41, +-18.5) mm from the
#   centre, countersunk 6 mm; two 2.5 mm height-screw holes on the long axis, 39 mm each side.
# - Template, 6 mm clear acrylic: 140 x 100 mm, corners r5; the cavity 73 x 41 mm with round
#   ears 10 mm across at the height screws (39 mm each side), every corner r3.175 for a 1/4 in
#   pattern bit; 1.5 mm marking holes where the ring's four screws go; centre lines engraved from
#   the cavity to the template's edges; "HUMBUCKER - 1/4 IN PATTERN BIT" engraved below the cavity.

BIT_R = 3.175 mm
SCREW_X = 41 mm
SCREW_Y = 18.5 mm
HEIGHT_X = 39 mm

assembly humbucker_kit {
    solid ring {
        thickness 3 mm
        body = RoundedRectangle(center=(0, 0), width=92, height=46, corner_radius=8)
        hole opening {
            r = RoundedRectangle(center=(0, 0), width=71, height=39.5, corner_radius=3)
        }
        hole screws {
            a = Circle(center=(-SCREW_X, -SCREW_Y), diameter=3)
            b = Circle(center=(SCREW_X, -SCREW_Y), diameter=3)
            c = Circle(center=(SCREW_X, SCREW_Y), diameter=3)
            d = Circle(center=(-SCREW_X, SCREW_Y), diameter=3)
        }
        Countersink(screws, diameter=6)
        hole height {
            a = Circle(center=(-HEIGHT_X, 0), diameter=2.5)
            b = Circle(center=(HEIGHT_X, 0), diameter=2.5)
        }
        assert body.bb.width == 92 mm and body.bb.height == 46 mm, "ring 92 x 46"
        assert opening.r.width - 70 mm == 1 mm and opening.r.height - 38.5 mm == 1 mm, "0.5 mm play round the pickup"
        assert screws.c.center.x - body.center.x == 41 mm, "screws at x 41"
        assert screws.c.center.y - body.center.y == 18.5 mm, "screws at y 18.5"
        assert height.b.center.x - body.center.x == 39 mm, "height screws 39 mm out"
    }

    solid template {
        thickness 6 mm
        body = RoundedRectangle(center=(0, 0), width=140, height=100, corner_radius=5)
        hole cavity {
            r = Rectangle(center=(0, 0), width=73, height=41)
            ear_l = Circle(center=(-HEIGHT_X, 0), diameter=10)
            ear_r = Circle(center=(HEIGHT_X, 0), diameter=10)
            Fillet(BIT_R)
        }
        hole marks {
            a = Circle(center=(-SCREW_X, -SCREW_Y), diameter=1.5)
            b = Circle(center=(SCREW_X, -SCREW_Y), diameter=1.5)
            c = Circle(center=(SCREW_X, SCREW_Y), diameter=1.5)
            d = Circle(center=(-SCREW_X, SCREW_Y), diameter=1.5)
        }
        drawing lines {
            left = Line((-70, 0), (-HEIGHT_X - 5, 0))
            right = Line((HEIGHT_X + 5, 0), (70, 0))
            top = Line((0, 20.5), (0, 50))
            bottom = Line((0, -50), (0, -20.5))
        }
        drawing label {
            t = Text("HUMBUCKER - 1/4 IN PATTERN BIT", position=(0, -35), size=4, valign="middle")
        }
        Fixed(body)
        assert cavity.r.width == 73 mm and cavity.r.height == 41 mm, "cavity 73 x 41"
        assert cavity.ear_r.center.x - body.center.x == 39 mm, "ears at the height screws"
        assert marks.c.center.x == SCREW_X and marks.c.center.y == SCREW_Y, "marks at the ring's screws"
        assert label.bb.top <= cavity.r.bb.bottom - 3 mm, "label below the cavity"
        assert label.bb.left >= body.bb.left + 5 mm and label.bb.right <= body.bb.right - 5 mm, "label on the template"
    }

    RightOf(template, ring, gap=10)
    AlignCenterY(template, ring)
}
