# Request: a lucky horseshoe for my sister's wedding, to hang open end up, in 3 mm birch ply.
# The shoe is 150 mm wide and 145 mm tall: a band 30 mm wide whose crown is a half ring
# (outer R75) and whose two branches run 70 mm straight up, closing in 4 mm each on the
# outside edge and 4 mm on the inside edge... (see below), heels rounded R6. Six nail
# holes 3 x 7 mm, three on each branch, 9 mm from the outer edge's line (on the line 66 mm
# from the crown's centre): at 200 and 222 degrees and 25 mm up the left branch, mirrored
# on the right. A 5 mm ribbon hole in each heel, 58 mm up. "ANNA & TOM" engraved filled
# (serif bold, 8 mm) along the crown, readable, centred at the bottom. A heart 44 wide
# hangs from the ribbon between the heels: two R12 lobes and a point, a 3 mm hole at the
# top, and the date "14.06.2027" engraved across it (at most 28 mm wide).
# The branches: outer edge from x = 75 at the crown's centre line to x = 67 at the top
# (closing in 8), inner edge from 45 to 41 (closing in 4).

units mm
thickness 3 mm

A_HOLES = [200 deg, 222 deg]
LEG_TILT = atan2(70, 6.8)          # the nail line up a branch: from x -66 to -59.2

assembly wedding_horseshoe {
    solid shoe {
        crown = Sector(center=(0, 0), radius=75, inner_radius=45, start_angle=180 deg,
                       end_angle=360 deg)
        leg_l = Polygon([(-75, 0), (-45, 0), (-41, 70), (-67, 70)])
        leg_r = Polygon([(75, 0), (67, 70), (41, 70), (45, 0)])
        Fillet([leg_l.points[2], leg_l.points[3], leg_r.points[1], leg_r.points[2]], 6)

        hole nails {
            for a in A_HOLES {
                nl = Rectangle(center=(66 * cos(a), 66 * sin(a)), width=3, height=7, rotation=a)
                nr = Rectangle(center=(-66 * cos(a), 66 * sin(a)), width=3, height=7,
                               rotation=180 deg - a)
            }
            ll = Rectangle(center=(-66 + 6.8 * 25 / 70, 25), width=3, height=7,
                           rotation=LEG_TILT - 90 deg)
            lr = Rectangle(center=(66 - 6.8 * 25 / 70, 25), width=3, height=7,
                           rotation=90 deg - LEG_TILT)
        }
        hole ribbon {
            l = Circle(center=(-60 + 6 * 58 / 70, 58), diameter=5)
            r = Circle(center=(60 - 6 * 58 / 70, 58), diameter=5)
        }
        drawing names {
            ring = Circle(center=(0, 0), radius=60, construction=true)
            t = Text("ANNA & TOM", along=ring, size=8, valign="middle", flip=true,
                     font="serif:Bold", fill=true)
        }
    }

    solid heart {
        lobe_l = Hull(Circle(center=(-10, 6), radius=12), Point(0, -20))
        lobe_r = Hull(Circle(center=(10, 6), radius=12), Point(0, -20))
        hole hang { c = Circle(center=(0, 7), diameter=3) }
        drawing date {
            t = Text("14.06.2027", position=(0, -3), size=4, valign="middle", max_width=28)
        }
        Rigid(self)
    }

    RightOf(heart, shoe, gap=10)
    AlignCenterY(heart, shoe)

    Place(shoe, position=(0, 0, 0), face="front", up="up")
    Place(heart, position=(0, 0, 20), face="front", up="up")

    assert shoe.bb.width == 150 mm, "150 wide"
    assert shoe.bb.height == 145 mm, "145 tall"
    assert shoe.crown.width == 30 mm, "band 30 wide"
    assert len(shoe.nails.nl) + len(shoe.nails.nr) + 2 == 6, "six nail holes"
    assert distance(shoe.names, shoe.nails) >= 2 mm, "the names clear the nail holes"
    assert shoe.ribbon.l.diameter == 5 mm, "5 mm ribbon holes"
    assert heart.bb.width == 44 mm, "heart 44 wide"
    assert heart.date.t.bb.width <= 28 mm, "date at most 28 wide"
    assert distance(heart.hang, heart.date) >= 2 mm, "the date clears the hanging hole"
}
