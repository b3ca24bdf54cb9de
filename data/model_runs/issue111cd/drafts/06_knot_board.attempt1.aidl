# Request (camping): a knot-tying board for our scout troop's camp, 6 mm ply, 400 x 300 mm,
# corners r15. Six knots in two rows of three, 120 mm apart across and 100 mm apart down:
# for each a pair of 5 mm holes 60 mm apart (a length of cord is threaded through and the knot
# tied in front) and its name engraved 22 mm under the holes, 7 mm letters: REEF KNOT,
# BOWLINE, CLOVE HITCH / SHEET BEND, TAUT-LINE HITCH, FIGURE EIGHT. The top row's holes
# 40 mm above the centre. "CAMP KNOTS" engraved filled in bold 20 mm letters, 120 mm above
# the centre. A rope border engraved 12 mm in from the edge: little ellipses 8 x 4 mm
# turned 45 deg, about 7 mm apart. Two 6 mm hanging holes 30 mm in from the top corners.

thickness 6 mm
names = ["REEF KNOT", "BOWLINE", "CLOVE HITCH", "SHEET BEND", "TAUT-LINE HITCH", "FIGURE EIGHT"]
col_dx = 120 mm
row_dy = 100 mm
bx = 188 mm     # the border's half width and half height
by = 138 mm
nx = 54
ny = 40

def cord_holes() -> hole {
    a = Circle(center=(-30, 0), diameter=5)
    b = Circle(center=(30, 0), diameter=5)
}

solid board {
    body = RoundedRectangle(center=(0, 0), width=400, height=300, corner_radius=15)

    first = cord_holes()
    At(first.a.center, body.center, dx=-col_dx - 30 mm, dy=40 mm)
    knots = GridPattern(first, 2, 3, (col_dx, -row_dy))

    hole hang {
        l = Circle(center=(-170, 120), diameter=6)
        r = Circle(center=(170, 120), diameter=6)
    }

    drawing labels {
        for i in range(6) {
            t = Text(names[i], ((i % 3 - 1) * col_dx, 40 mm - (i // 3) * row_dy - 22 mm),
                     size=7, valign="middle")
        }
    }

    drawing title {
        t = Text("CAMP KNOTS", (0, 120), size=20, font="sans:Bold", fill=true, valign="middle")
    }

    drawing rope {
        top0 = Ellipse(center=(-bx, by), rx=4, ry=2, rotation=45 deg)
        bot0 = Ellipse(center=(-bx, -by), rx=4, ry=2, rotation=45 deg)
        lef0 = Ellipse(center=(-bx, -by + 2 * by / (ny - 1)), rx=4, ry=2, rotation=45 deg)
        rig0 = Ellipse(center=(bx, -by + 2 * by / (ny - 1)), rx=4, ry=2, rotation=45 deg)
        top = LinearPattern(top0, nx, (2 * bx / (nx - 1), 0))
        bot = LinearPattern(bot0, nx, (2 * bx / (nx - 1), 0))
        lef = LinearPattern(lef0, ny - 2, (0, 2 * by / (ny - 1)))
        rig = LinearPattern(rig0, ny - 2, (0, 2 * by / (ny - 1)))
    }

    assert body.bb.width == 400 mm and body.bb.height == 300 mm, "board 400 x 300"
    assert len(knots) == 6 and len(names) == 6, "six knots"
    assert knots[1].a.center.x - knots[0].a.center.x == 120 mm, "120 apart across"
    assert knots[0].a.center.y - knots[3].a.center.y == 100 mm, "100 apart down"
    assert knots[0].b.center.x - knots[0].a.center.x == 60 mm, "holes 60 apart"
    assert knots[0].a.center.y - body.center.y == 40 mm, "top row 40 above the centre"
    assert body.bb.top - title.t.bb.top > 12 mm + 3 mm, "title inside the rope border"
    assert top[1].center.x - top[0].center.x < 7.5 mm, "rope about 7 mm pitch"
}
