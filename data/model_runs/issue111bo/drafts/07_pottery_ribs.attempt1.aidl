# Request: a set of four pottery ribs for throwing and trimming, 3 mm acrylic, each with an
# 8 mm hole to hang it on a peg board and its name engraved (5 mm single-stroke letters).
# - KIDNEY: a 110 x 60 oval with a shallow concave bite 12 mm deep (r60) in its top edge.
# - SCRAPER: 100 x 50, a straight bottom edge with sharp corners, its top corners rounded 25.
# - BOWL: a half disc r60 for bowl insides, its two corners rounded 3 mm.
# - TEETH: 100 x 40 (top corners rounded 10), 15 triangular notches 5 wide and 5 deep at
#   6 mm pitch along the bottom edge for scoring.

units mm
thickness 3 mm

assembly ribs {
    solid kidney {
        body = Ellipse(center=(0, 0), rx=55, ry=30)
        hole bite {
            c = Circle(center=(0, 30 - 12 + 60), radius=60)
        }
        hole hang {
            c = Circle(center=(-38, -4), diameter=8)
        }
        drawing name {
            t = Text("KIDNEY", position=(6, -14), size=5)
        }
    }

    solid scraper {
        body = RoundedRectangle(center=(0, 0), width=100, height=50, corner_radii=[25, 25, 0, 0])
        hole hang {
            c = Circle(center=(0, 12), diameter=8)
        }
        drawing name {
            t = Text("SCRAPER", position=(0, -10), size=5)
        }
    }

    solid bowl {
        body = Sector(center=(0, 0), radius=60, start_angle=0, end_angle=180 deg)
        hole hang {
            c = Circle(center=(0, 40), diameter=8)
        }
        drawing name {
            t = Text("BOWL", position=(0, 12), size=5)
        }
        Fillet([body.start, body.end], 3)
    }

    solid teeth {
        body = RoundedRectangle(center=(0, 0), width=100, height=40, corner_radii=[10, 10, 0, 0])
        hole notch {
            t = Triangle(center=(-42, -20 + 1.5), base=5, height=5)   # base 1 mm below the edge
        }
        row = LinearPattern(notch, 15, (6, 0))
        hole hang {
            c = Circle(center=(0, 8), diameter=8)
        }
        drawing name {
            t = Text("TEETH", position=(0, -6), size=5)
        }
    }

    # on the sheet: a row, 10 mm apart
    scraper.body.bb.left == kidney.body.bb.right + 10
    AlignBottom(scraper.body, kidney.body)
    bowl.body.bb.left == scraper.body.bb.right + 10
    AlignBottom(bowl.body, kidney.body)
    teeth.body.bb.left == bowl.body.bb.right + 10
    AlignBottom(teeth.body, kidney.body)

    # the request's numbers
    assert kidney.body.bb.width == 110 mm and kidney.body.bb.height == 60 mm, "kidney 110 x 60"
    assert kidney.body.bb.top - kidney.bite.c.bb.bottom == 12 mm, "bite 12 deep"
    assert kidney.bite.c.radius == 60 mm, "bite r60"
    assert scraper.body.bb.width == 100 mm and scraper.body.bb.height == 50 mm, "scraper 100 x 50"
    assert bowl.body.radius == 60 mm, "bowl r60"
    assert teeth.body.bb.width == 100 mm and teeth.body.bb.height == 40 mm, "teeth 100 x 40"
    assert len(teeth.row) == 15, "15 notches"
    assert teeth.row[1].t.center.x - teeth.row[0].t.center.x == 6 mm, "6 mm pitch"
    assert teeth.row[14].bb.right < teeth.body.bb.right and teeth.row[0].bb.left > teeth.body.bb.left,
        "notches within the edge"
    assert teeth.notch.t.bb.top - teeth.body.bb.bottom == 5 mm, "notches 5 deep"
    assert kidney.hang.c.diameter == 8 mm and scraper.hang.c.diameter == 8 mm and
        bowl.hang.c.diameter == 8 mm and teeth.hang.c.diameter == 8 mm, "8 mm hang holes"
}
