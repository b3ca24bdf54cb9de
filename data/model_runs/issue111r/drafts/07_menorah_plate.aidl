# Hanukkah menorah top plate (holidays): a 6 mm plate 300 x 60 mm, corners R6, with a
# half-round bump R30 rising from the middle of its top edge (total height 90 mm); eight
# 13 mm candle holes in two groups of four, 30 mm apart, their centres on the plate's
# middle line, the two inner holes 45 mm either side of the centre; the shamash's 13 mm
# hole in the bump, 15 mm above the top edge; a Star of David (two 24 mm triangles,
# one pointing up, one down) engraved 8 mm below the middle line, centred... actually
# under the shamash: centred left-right, its centre 15 mm above the bottom edge.
thickness 6 mm

param pitch = 30 mm, min = 25 mm, max = 35 mm
param candle = 13 mm, min = 10 mm, max = 16 mm

solid menorah {
    body = RoundedRectangle(center=(0, 0), width=300, height=60, corner_radius=6)
    bump = Circle(center=(0, 30), radius=30)
    axis = Line((0, -50), (0, 80), construction=true)

    hole c {
        h = Circle(center=(-45, 0), diameter=candle)
    }
    left = LinearPattern(c, 4, (-pitch, 0))
    right = Mirrored(left, about=axis)

    hole shamash {
        h = Circle(center=(0, 45), diameter=candle)
    }

    drawing star {
        # a hexagram: the centroids (not the boxes' centres) meet at y = -15
        up = Triangle(center=(0, -15 + 20.78 / 6), base=24, height=20.78)
        down = Triangle(center=(0, -15 - 20.78 / 6), base=24, height=20.78, rotation=180)
    }

    assert body.bb.width == 300 mm and body.bb.height == 60 mm, "300 x 60 plate"
    assert self.bb.height == 90 mm, "90 tall with the bump"
    assert len(left) + len(right) == 8, "eight candles"
    assert c.h.center.x - left[1].h.center.x == 30 mm, "30 apart"
    assert right[0].h.center.x == 45 mm, "inner holes 45 from the centre"
    assert shamash.h.center.y - body.bb.top == 15 mm, "shamash 15 above the top edge"
}
