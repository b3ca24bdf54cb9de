# Request: twelve dies for a polymer-clay extruder gun (barrel bore 25.4 mm), cut from
# 2 mm clear acrylic: discs 25.0 mm across, each with one profile opening in the middle and
# its number (1-12, 3 mm figures) engraved 9.5 mm below the centre. The profiles:
# 1 round 3 mm, 2 round 5 mm, 3 square 4 mm, 4 triangle 5 mm (pointing up), 5 five-point
# star 7 mm across the tips, 6 heart about 6 mm, 7 hexagon 5 mm across flats, 8 ribbon
# 10 x 2 mm, 9 half moon 6 mm (radius 3), 10 plus 6 mm (arms 1.6 mm), 11 trefoil of three
# 2 mm holes on a 2 mm radius, 12 grass: nine 1 mm holes on a 2.5 mm grid.
# A storage tray from two 3 mm ply plates 150 x 130 mm, R6 corners, glued together: the
# top plate has 4 x 3 pockets 25.6 mm across (34 mm apart across, 42 mm down), each with
# a 10 mm thumb notch on its right, and each pocket's name engraved under it (3 mm
# letters, at most 30 mm long); the bottom plate is plain.

units mm
thickness 3 mm

names = ["1 ROUND 3", "2 ROUND 5", "3 SQUARE 4", "4 TRIANGLE 5", "5 STAR 7", "6 HEART 6",
         "7 HEX 5", "8 RIBBON 10", "9 HALF MOON 6", "10 PLUS 6", "11 TREFOIL", "12 GRASS"]
def px(i) = (i % 4 - 1.5) * 34 mm
def py(i) = (1 - i // 4) * 42 mm

def die(kind=1) -> solid {
    thickness 2 mm
    disc = Circle(center=(0, 0), diameter=25)
    hole profile {
        if kind == 1 {
            c = Circle(center=(0, 0), diameter=3)
        } elif kind == 2 {
            c = Circle(center=(0, 0), diameter=5)
        } elif kind == 3 {
            c = Rectangle(center=(0, 0), width=4, height=4)
        } elif kind == 4 {
            c = Triangle(center=(0, 0), base=5, height=5 * sqrt(3) / 2)
        } elif kind == 5 {
            c = Star(center=(0, 0), points=5, outer_radius=3.5, inner_radius=1.5)
        } elif kind == 6 {
            c = Hull(Circle(center=(-1.3, 0.9), radius=1.6), Point(0, -2.8))
            c2 = Hull(Circle(center=(1.3, 0.9), radius=1.6), Point(0, -2.8))
        } elif kind == 7 {
            c = RegularPolygon(center=(0, 0), across_flats=5, sides=6)
        } elif kind == 8 {
            c = Rectangle(center=(0, 0), width=10, height=2)
        } elif kind == 9 {
            c = Sector(center=(0, -1.5), radius=3, start_angle=0 deg, end_angle=180 deg)
        } elif kind == 10 {
            c = Rectangle(center=(0, 0), width=6, height=1.6)
            c2 = Rectangle(center=(0, 0), width=1.6, height=6)
        } elif kind == 11 {
            for j in range(3) {
                c = Circle(center=polar((0, 0), 2, 90 deg + j * 120 deg), diameter=2)
            }
        } else {
            for j in range(9) {
                c = Circle(center=((j % 3 - 1) * 2.5, (j // 3 - 1) * 2.5), diameter=1)
            }
        }
    }
    drawing number {
        t = Text(str(kind), position=(0, -9.5), size=3, valign="middle")
    }
}

assembly clay_dies {
    for i in range(12) {
        d = die(kind=i + 1)
        d.disc.center == (i % 4 * 30, -(i // 4) * 30)
        # assembled: each die in its pocket, on the bottom plate
        Place(d, position=(px(i), py(i), 3), face="up")
    }
    solid top {
        plate = RoundedRectangle(center=(0, -2), width=150, height=130, corner_radius=6)
        hole pockets {
            for i in range(12) {
                c = Circle(center=(px(i), py(i)), diameter=25.6)
                notch = Circle(center=(px(i) + 12.8, py(i)), diameter=10)
            }
            # FIX after the first valid program: the thumb notch is meant to bite into
            # its pocket (W0512, a false alarm here): say so
            AllowOverlap(c, notch)
        }
        drawing labels {
            for i in range(12) {
                t = Text(names[i], position=(px(i), py(i) - 17), size=3, valign="middle",
                         max_width=30)
            }
        }
    }
    solid bottom {
        plate = RoundedRectangle(center=(0, -2), width=150, height=130, corner_radius=6)
    }
    RightOf(top, d[3], gap=10)
    AlignTop(top, d[0])
    RightOf(bottom, top, gap=5)
    AlignTop(bottom, top)
    Place(bottom, position=(0, 0, 0), face="up")
    Place(top, position=(0, 0, 3), face="up")

    # the request's numbers
    assert len(d) == 12 and len(top.pockets.c) == 12 and len(top.labels.t) == 12, "twelve of each"
    assert d[0].disc.diameter == 25 mm and d[0].disc.diameter < 25.4 mm, "25.0 discs for a 25.4 bore"
    assert d[0].profile.c.diameter == 3 mm and d[1].profile.c.diameter == 5 mm, "round 3 and 5"
    assert d[2].profile.c.width == 4 mm, "square 4"
    assert d[3].profile.c.base == 5 mm, "triangle 5"
    assert d[4].profile.c.outer_radius * 2 == 7 mm, "star 7"
    assert d[6].profile.c.across_flats == 5 mm, "hex 5"
    assert d[7].profile.c.width == 10 mm and d[7].profile.c.height == 2 mm, "ribbon 10 x 2"
    assert d[8].profile.c.radius == 3 mm, "half moon radius 3"
    assert d[9].profile.c.width == 6 mm and d[9].profile.c.height == 1.6 mm, "plus 6, arms 1.6"
    assert len(d[10].profile.c) == 3 and d[10].profile.c[0].diameter == 2 mm, "trefoil: three 2 mm"
    assert len(d[11].profile.c) == 9 and d[11].profile.c[0].diameter == 1 mm, "grass: nine 1 mm"
    assert d[11].profile.c[1].center.x - d[11].profile.c[0].center.x == 2.5 mm, "2.5 grid"
    assert d[0].disc.center.y - d[0].number.t.position.y == 9.5 mm, "number 9.5 below centre"
    assert top.plate.width == 150 mm and top.plate.height == 130 mm, "plates 150 x 130"
    assert top.pockets.c[0].diameter == 25.6 mm, "pockets 25.6"
    assert top.pockets.c[1].center.x - top.pockets.c[0].center.x == 34 mm, "34 across"
    assert top.pockets.c[0].center.y - top.pockets.c[4].center.y == 42 mm, "42 down"
    assert top.pockets.notch[0].diameter == 10 mm, "10 mm notch"
    assert top.labels.t[8].bb.width <= 30 mm, "names at most 30 long"
    assert top.pockets.bb.left - top.plate.bb.left >= 3 mm and top.plate.bb.right - top.pockets.bb.right >= 3 mm,
        "pockets inside the plate"
    assert top.labels.bb.bottom - top.plate.bb.bottom >= 3 mm, "labels on the plate"
}
