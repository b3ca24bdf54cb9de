# Request (gifts): a wedding-date calendar plaque to hang on a ribbon, 3 mm birch ply,
# 200 x 250 with 8 mm corners. "OUR DAY" (bold, filled, 16 mm) centred 90 mm above the
# plaque's centre, "JUNE 2025" (serif, filled, 10 mm) 62 mm above it. Below, a Monday-first
# month grid of June 2025 (the 1st is a Sunday): day headers M T W T F S S in single-stroke
# 7 mm letters 38 mm above the centre, the 30 days in single-stroke 7 mm numbers, columns
# 24 mm apart centred on the plaque, rows 18 mm apart, the first row 18 mm above the centre.
# The wedding day, the 14th, has no number: a heart 17 mm wide and 15 mm tall is cut
# through the plaque in its place. "ANNA & LUCA" (serif, filled, 12 mm) 100 mm below the
# centre. Two 4 mm ribbon holes 15 mm in from the top corners' sides and top.

units mm
thickness 3 mm

col = 24 mm
row = 18 mm
first_col = 6          # June 1, 2025 is a Sunday: the 7th column of a Monday-first week
wedding = 14
names = ["M", "T", "W", "T", "F", "S", "S"]

def cell_x(d) = -3 * col + ((d - 1 + first_col) % 7) * col
def cell_y(d) = row - ((d - 1 + first_col) // 7) * row

solid plaque {
    body = RoundedRectangle(center=(0, 0), width=200, height=250, corner_radius=8)

    drawing title {
        a = Text("OUR DAY", position=(0, 90), size=16, font="sans:Bold", fill=true,
                 valign="middle")
        b = Text("JUNE 2025", position=(0, 62), size=10, font="serif", fill=true,
                 valign="middle")
    }

    drawing header {
        for c in range(7) {
            h = Text(names[c], position=(-3 * col + c * col, 38), size=7, valign="middle")
        }
    }

    drawing days {
        for d in range(1, 31) {
            if d != wedding {
                n = Text(str(d), position=(cell_x(d), cell_y(d)), size=7, valign="middle")
            }
        }
    }

    hole heart {
        l = Hull(Circle(center=(cell_x(wedding) - 4, cell_y(wedding) + 2.5), radius=4.5),
                 Point(cell_x(wedding), cell_y(wedding) - 8))
        r = Hull(Circle(center=(cell_x(wedding) + 4, cell_y(wedding) + 2.5), radius=4.5),
                 Point(cell_x(wedding), cell_y(wedding) - 8))
    }

    drawing couple {
        c = Text("ANNA & LUCA", position=(0, -100), size=12, font="serif", fill=true,
                 valign="middle")
    }

    hole ribbon {
        h1 = Circle(center=(-100 + 15, 125 - 15), diameter=4)
        h2 = Circle(center=(100 - 15, 125 - 15), diameter=4)
    }

    assert body.bb.width == 200 mm and body.bb.height == 250 mm, "200 x 250"
    assert len(days.n) == 29, "30 days, the 14th a heart"
    assert len(header.h) == 7, "seven day names"
    assert days.n[0].position.x == header.h[6].position.x, "the 1st on a Sunday"
    assert days.n[0].position.y - body.center.y == 18 mm, "first row 18 above the centre"
    assert heart.bb.width == 17 mm and heart.bb.height == 15 mm, "heart 17 x 15"
    assert heart.bb.center_x == header.h[5].position.x, "the 14th is a Saturday"
    assert title.a.position.y - body.center.y == 90 mm, "title 90 above the centre"
    assert couple.c.position.y - body.center.y == -100 mm, "names 100 below the centre"
    assert body.bb.top - ribbon.h1.center.y == 15 mm and ribbon.h1.center.x - body.bb.left == 15 mm, "ribbon holes 15 in"
}
