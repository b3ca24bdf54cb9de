# Request: five clothes-rail size dividers for my wardrobe (25 mm round rail), cut from 3 mm
# acrylic. Each is a 100 mm disc with a 26 mm hole for the rail, its centre 20 mm above the
# disc's centre, and a 26 mm wide straight slot from the hole out through the top edge so the
# divider drops onto the rail. Below the hole the size is fill-engraved in bold letters 24 mm
# tall: XS, S, M, L, XL (one disc each). An engraved ring 5 mm in from the edge, broken where
# the slot is (3 mm clear of the slot on each side). Lay the five out in a row, 5 mm apart.

units mm
thickness 3 mm

SIZES = ["XS", "S", "M", "L", "XL"]

def divider(label="M") -> solid {
    disc = Circle(center=(0, 0), diameter=100)
    hole rail {
        c = Circle(center=(0, 20), diameter=26)
        s = Rectangle(center=(0, 40), width=26, height=40, overrun=true)
    }
    drawing size {
        t = Text(label, position=(0, -22), size=24, font="sans:Bold", valign="middle",
                 fill=true)
    }
    drawing rim {
        # the ring 5 mm in (radius 45), broken 3 mm clear of the 26 mm slot
        a = Arc(center=(0, 0), radius=45, start_angle=90 deg + asin(16 / 45),
                end_angle=90 deg - asin(16 / 45))
    }
    assert disc.diameter == 100 mm, "100 mm disc"
    assert rail.c.diameter == 26 mm, "26 mm rail hole"
    assert rail.s.width == 26 mm, "26 mm slot"
    assert rail.c.center.y - disc.center.y == 20 mm, "hole centre 20 mm above the disc centre"
    assert size.t.size == 24 mm, "letters 24 mm tall"
    assert distance(size, rail) >= 3 mm, "size clear of the rail hole"
    assert size.bb.bottom >= disc.bb.bottom + 5 mm, "size inside the disc"
    assert disc.radius - rim.a.radius == 5 mm, "ring 5 mm in from the edge"
}

assembly dividers {
    for i in range(5) {
        d = divider(label=SIZES[i])
    }
    for i in range(1, 5) {
        RightOf(d[i], d[i - 1], gap=5)
        AlignCenterY(d[i], d[i - 1])
    }
    assert len(d) == 5, "five dividers"
    assert d[1].bb.left - d[0].bb.right == 5 mm, "5 mm apart"
}
