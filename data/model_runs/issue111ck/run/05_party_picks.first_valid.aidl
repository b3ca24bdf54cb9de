# Request (parties): six canape picks for a 30th birthday, in 3 mm birch plywood, cut as
# separate pieces. Each pick is a 4 mm wide shaft whose tip is 80 mm below the middle of its
# head; the last 15 mm taper to a sharp point (the point is meant sharp). Heads: two 5-point
# stars (tips 12 mm, notches 5 mm from the centre), two hearts 22 mm wide, and two 26 mm discs
# with "30" cut right through in bold stencil letters 11 mm tall. Picks 6 mm apart on the sheet.

thickness 3 mm
min_wall 0.3 mm    # the picks' points are meant sharp

shaft_w = 4 mm
reach = 80 mm      # head centre to tip
taper = 15 mm

def pick(kind="star") -> solid {
    shaft = Polygon([(-shaft_w / 2, 0), (shaft_w / 2, 0), (shaft_w / 2, -(reach - taper)),
                     (0, -reach), (-shaft_w / 2, -(reach - taper))])
    if kind == "star" {
        head = Star(center=(0, 0), points=5, outer_radius=12, inner_radius=5)
    } else {
        if kind == "heart" {
            lobe_l = Hull(Circle(center=(-5, 3), radius=6), Point(0, -10))
            lobe_r = Hull(Circle(center=(5, 3), radius=6), Point(0, -10))
        } else {
            disc = Circle(center=(0, 0), diameter=26)
            hole number {
                n = Text("30", position=(0, 0), size=11, valign="middle", font="sans:Bold",
                         stencil=true)
            }
        }
    }
}

assembly picks {
    star1 = pick(kind="star")
    star2 = pick(kind="star")
    heart1 = pick(kind="heart")
    heart2 = pick(kind="heart")
    disc1 = pick(kind="disc")
    disc2 = pick(kind="disc")

    RightOf(star2, star1, gap=6)
    RightOf(heart1, star2, gap=6)
    RightOf(heart2, heart1, gap=6)
    RightOf(disc1, heart2, gap=6)
    RightOf(disc2, disc1, gap=6)
    AlignBottom(star2, star1)
    AlignBottom(heart1, star1)
    AlignBottom(heart2, star1)
    AlignBottom(disc1, star1)
    AlignBottom(disc2, star1)

    # the request's numbers
    assert star1.shaft.bb.width == 4 mm, "shaft 4 mm wide"
    assert star1.head.center.y - star1.shaft.points[3].y == 80 mm, "tip 80 mm below the head"
    assert star1.shaft.points[2].y - star1.shaft.points[3].y == 15 mm, "15 mm taper"
    assert star1.head.outer_radius == 12 mm and star1.head.inner_radius == 5 mm, "star"
    assert heart1.bb.width == 22 mm, "heart 22 mm wide"
    assert disc1.disc.diameter == 26 mm, "disc 26 mm"
    assert disc1.number.n.size == 11 mm, "numbers 11 mm tall"
}
