# Request (toys): a Nine Men's Morris set in 4 mm plywood. The board is two 220 x 240 mm
# plates (4 mm corner radius) glued together: the top plate has 24 pockets of 21 mm diameter
# at the game's points (three concentric squares of 180, 120 and 60 mm side, points at
# their corners and edge middles) with the squares' lines and the four cross lines engraved
# between the pockets, and "NINE MEN'S MORRIS" engraved 6 mm tall in the 20 mm strip under
# the playing field; the bottom plate is plain. 18 counters of 20 mm diameter: 9 dark ones
# with their face engraved filled (17 mm disc) and 9 plain ones. Show the set assembled with
# counters sitting in pockets.

thickness 4 mm

param pocket_d = 21 mm, min = 20.5 mm, max = 23 mm
param counter_d = 20 mm, min = 15 mm, max = 20 mm

corner_dir = [(-1, -1), (0, -1), (1, -1), (1, 0), (1, 1), (0, 1), (-1, 1), (-1, 0)]
halves = [90, 60, 30]
pts = [(corner_dir[i % 8][0] * halves[i // 8], corner_dir[i % 8][1] * halves[i // 8])
       for i in range(24)]

def counter(dark=false) -> solid {
    disc = Circle(center=(0, 0), diameter=counter_d)
    if dark {
        drawing face {
            f = Circle(center=(0, 0), diameter=17, fill=true)
        }
    }
}

assembly morris {
    solid base {
        plate = RoundedRectangle(center=(0, -10), width=220, height=240, corner_radius=4)
    }

    solid top {
        plate = RoundedRectangle(center=(0, -10), width=220, height=240, corner_radius=4)
        hole pockets {
            for i in range(24) {
                p = Circle(center=pts[i], diameter=pocket_d)
            }
        }
        drawing lines {
            outer = Rectangle(center=(0, 0), width=180, height=180)
            middle = Rectangle(center=(0, 0), width=120, height=120)
            inner = Rectangle(center=(0, 0), width=60, height=60)
            cross_l = Line((-90, 0), (-30, 0))
            cross_r = Line((30, 0), (90, 0))
            cross_b = Line((0, -90), (0, -30))
            cross_t = Line((0, 30), (0, 90))
            hole mask {
                for i in range(24) {
                    m = Circle(center=pts[i], diameter=pocket_d)
                }
            }
        }
        drawing title {
            t = Text("NINE MEN'S MORRIS", position=(0, -122), size=6)
        }
    }

    for i in range(18) {
        c = counter(dark=(i < 9))
        At(c.disc.center, top.plate.center, dx=150 + (i % 3) * 25, dy=90 - (i // 3) * 25)
        # assembled: dark counters on the outer square's points, plain ones on the middle's
        Place(c, position=(pts[i if i < 9 else i + 3][0], pts[i if i < 9 else i + 3][1], 4))
    }

    RightOf(top, base, gap=10)
    AlignCenterY(top, base)
    Place(base, position=(0, 0, 0))
    Place(top, position=(0, 0, 4))

    assert len(top.pockets.p) == 24, "24 points"
    assert len(c) == 18, "18 counters"
    assert top.lines.outer.width == 180 mm and top.lines.middle.width == 120 mm and top.lines.inner.width == 60 mm
    assert top.plate.width == 220 mm and top.plate.height == 240 mm
    assert top.pockets.p[0].diameter == 21 mm and c[0].disc.diameter == 20 mm
    assert top.lines.outer.bb.bottom - top.plate.bb.bottom == 20 mm + pocket_d / 2 + 9.5 mm - 9.5 mm, "20 mm title strip under the field"
}
