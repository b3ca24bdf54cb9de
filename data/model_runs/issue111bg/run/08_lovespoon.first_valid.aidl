# Request (gifts): a Welsh lovespoon as a wedding present, to hang on the wall, cut from 4 mm
# cherry-faced ply. 250 mm long overall: an oval bowl 56 mm wide and 80 mm long at the bottom;
# a handle that tapers from 16 mm at the bowl to 24 mm at the top, with two heart-shaped
# piercings 13 mm wide, 24 mm apart; a heart crest 60 mm wide on top with a 5 mm hanging hole;
# the joins rounded (R5 at the bowl, R4 at the crest). Engraved: the bowl's dish as an oval
# line 44 x 66 mm, the names "ELIN", "&", "RHYS" stacked in it in filled serif letters 7 mm
# high, and the wedding date "14.02.2027" 4.5 mm high running up the handle.

units mm
thickness 4 mm

def heart_hole(cy=0 mm) -> hole {
    hl = Hull(Circle(center=(-3, cy + 3), radius=3.5), Point(0, cy - 8))
    hr = Hull(Circle(center=(3, cy + 3), radius=3.5), Point(0, cy - 8))
}

# the crest: a square turned 45 deg with a circle on each upper side (diameter = the side)
K = 1 / (2 * sqrt(2)) + 0.5        # half the heart's width, per unit of side
SIDE = 60 mm / (2 * K)
YC = 250 mm - K * SIDE             # the square's centre: the lobes' tops at 250

solid spoon {
    bowl = Ellipse(center=(0, 40), rx=28, ry=40)
    # (attempt 1: the handle and the crest were Hulls, which Fillet at a crossing refuses)
    handle = Trapezoid(center=(0, (70 + 215) / 2), bottom_width=16, top_width=24,
                       height=215 - 70)
    crest_sq = Rectangle(center=(0, YC), width=SIDE, height=SIDE, rotation=45 deg)
    lobe_l = Circle(center=(-SIDE / (2 * sqrt(2)), YC + SIDE / (2 * sqrt(2))), diameter=SIDE)
    lobe_r = Circle(center=(SIDE / (2 * sqrt(2)), YC + SIDE / (2 * sqrt(2))), diameter=SIDE)
    Fillet([handle, bowl], 5)
    Fillet([handle, crest_sq], 4)

    low_heart = heart_hole(cy=152 mm)
    high_heart = heart_hole(cy=176 mm)
    hole hang { c = Circle(center=(0, 234), diameter=5) }

    drawing dish {
        rim = Ellipse(center=(0, 42), rx=22, ry=33)
        n1 = Text("ELIN", position=(0, 53), size=7, font="serif:Bold", valign="middle", fill=true)
        amp = Text("&", position=(0, 42), size=7, font="serif:Bold", valign="middle", fill=true)
        n2 = Text("RHYS", position=(0, 31), size=7, font="serif:Bold", valign="middle", fill=true)
    }
    drawing date {
        d = Text("14.02.2027", position=(0, 112), size=4.5, valign="middle", rotation=90 deg)
    }

    # the request's numbers
    assert self.bb.height == 250 mm, "250 long"
    assert bowl.rx * 2 == 56 mm and bowl.ry * 2 == 80 mm, "bowl 56 x 80"
    assert lobe_r.bb.right - lobe_l.bb.left == 60 mm, "crest 60 wide"
    assert low_heart.bb.width == 13 mm, "hearts 13 wide"
    assert high_heart.hl.bb.bottom - low_heart.hl.bb.bottom == 24 mm, "hearts 24 apart"
    assert hang.c.diameter == 5 mm, "5 mm hanging hole"
    assert dish.rim.rx * 2 == 44 mm and dish.rim.ry * 2 == 66 mm, "dish line 44 x 66"
    assert dish.n1.bb.width <= 40 mm and dish.n2.bb.width <= 40 mm, "names inside the dish"
    assert date.bb.top <= low_heart.bb.bottom - 5 mm, "date below the hearts"
    assert date.bb.width <= 16 mm - 2 * 4 mm, "date across the handle"
}
