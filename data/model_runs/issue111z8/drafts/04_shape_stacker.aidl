# Toys: a shape-stacking toy of 6 mm plywood. A base 110 x 110 mm with 10 mm
# corner radius, a 12 mm hole in its centre for a 12 mm dowel post, and
# "STACK ME" engraved 7 mm tall, its baseline 12 mm above the bottom edge.
# Four pieces to stack on the post, each with a 14 mm bore in its centre:
# a disc 90 mm across, a hexagon 75 mm across flats, a 5-pointed star of outer
# radius 32 and inner radius 18 with 3 mm rounded tips, and a square 45 x 45
# with 6 mm corner radius. Edges of a toddler's toy: no sharp tips.

units mm
thickness 6 mm

def bore() -> hole {
    c = Circle(center=(0, 0), diameter=14)
}

assembly stacker {
    solid base {
        body = RoundedRectangle(center=(0, 0), width=110, height=110, corner_radius=10)
        hole post {
            c = Circle(center=(0, 0), diameter=12)
        }
        drawing label {
            t = Text("STACK ME", position=(0, -55 + 12), size=7)
        }
    }
    solid disc {
        s = Circle(center=(0, 0), diameter=90)
        b = bore()
        Concentric(b.c, s)
    }
    solid hexagon {
        s = RegularPolygon(center=(0, 0), across_flats=75, sides=6)
        b = bore()
        Concentric(b.c, s)
    }
    solid star {
        s = Star(center=(0, 0), points=5, outer_radius=32, inner_radius=18, tip_radius=3)
        b = bore()
        Concentric(b.c, s)
    }
    solid square {
        s = RoundedRectangle(center=(0, 0), width=45, height=45, corner_radius=6)
        b = bore()
        Concentric(b.c, s)
    }
    RightOf(disc, base, gap=6)
    RightOf(hexagon, disc, gap=6)
    RightOf(star, hexagon, gap=6)
    RightOf(square, star, gap=6)
    AlignCenterY(disc, base)
    AlignCenterY(hexagon, base)
    AlignCenterY(star, base)
    AlignCenterY(square, base)

    assert base.body.bb.width == 110 mm and base.body.bb.height == 110 mm, "base 110 x 110"
    assert base.post.c.diameter == 12 mm, "post hole 12"
    assert base.label.t.position.y - base.body.bb.bottom == 12 mm, "label 12 above the bottom"
    assert disc.s.diameter == 90 mm, "disc 90"
    assert hexagon.s.bb.height == 75 mm, "hexagon 75 across flats"
    assert star.s.outer_radius == 32 mm and star.s.inner_radius == 18 mm, "star 32 / 18"
    assert square.s.width == 45 mm, "square 45"
    assert disc.b.c.diameter == 14 mm and star.b.c.diameter == 14 mm, "bores 14"
}
