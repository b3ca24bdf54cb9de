# Request: bases for weaving cane baskets, cut from 4 mm birch ply, with holes for 2.5 mm
# round cane stakes (3.2 mm holes) 8 mm in from the edge, evenly spaced along the edge:
# - a round base 150 mm across with 28 holes;
# - an oval (racetrack) base 240 x 150 mm, its ends full semicircles, with 40 holes spaced
#   equally along the path 8 mm in from the edge (about 15 mm apart, straights and curves
#   alike), the first half a spacing from the start of the top straight.
# Each engraved in the middle with its size and stake count: "ROUND 150 - 28 STAKES",
# "OVAL 240 x 150 - 40 STAKES".

thickness 4 mm

hole_d = 3.2 mm
inset = 8 mm
# the oval: outer 240 x 150; the holes' path 8 mm in
OL = 240 mm
OW = 150 mm
r = OW / 2 - inset                # the path's end radius
Ls = OL - OW                      # straight between the ends' centres
per = 2 * Ls + 2 * pi * r         # the path's length
n_oval = 40
sp = per / n_oval

# a point at distance d along the path, from the top straight's left end, clockwise
def path_pt(d) = ((-Ls / 2 + d, r) if d < Ls else
    (polar((Ls / 2, 0), r, 90 deg - (d - Ls) / r * 1 rad) if d < Ls + pi * r else
    ((Ls / 2 - (d - Ls - pi * r), -r) if d < 2 * Ls + pi * r else
    polar((-Ls / 2, 0), r, -90 deg - (d - 2 * Ls - pi * r) / r * 1 rad))))

assembly basket_bases {
    solid round_base {
        disc = Circle(center=(0, 0), diameter=150 mm)
        hole stake {
            c = Circle(center=(75 mm - inset, 0), diameter=hole_d)
        }
        ring = CircularPattern(stake, 28, disc.center)
        drawing label {
            l = Text("ROUND 150 - 28 STAKES", position=(0, 0), size=6, valign="middle")
        }
    }
    solid oval_base {
        body = Slot(center=(0, 0), length=OL, width=OW)
        hole stakes {
            for i in range(n_oval) {
                c = Circle(center=path_pt(sp * (i + 0.5)), diameter=hole_d)
            }
        }
        drawing label {
            l = Text("OVAL 240 x 150 - 40 STAKES", position=(0, 0), size=7, valign="middle")
        }
    }
    RightOf(oval_base, round_base, gap=10)
    AlignCenterY(oval_base, round_base)

    # the request's numbers
    assert round_base.disc.diameter == 150 mm and len(round_base.ring) == 28, "round: 150 mm, 28 holes"
    assert oval_base.body.bb.width == 240 mm and oval_base.body.bb.height == 150 mm, "oval 240 x 150"
    assert len(oval_base.stakes.c) == 40, "oval: 40 holes"
    assert round_base.disc.radius - distance(round_base.ring[5].c.center, round_base.disc.center) == 8 mm,
        "round: holes 8 mm in"
    assert oval_base.body.bb.top - oval_base.stakes.c[0].center.y == 8 mm, "oval: holes 8 mm in (straight)"
    assert oval_base.body.bb.right - oval_base.stakes.c[n_oval / 4].center.x >= 8 mm - 0.01 mm,
        "oval: holes at least 8 mm in (end)"
    assert sp >= 14.5 mm and sp <= 15.5 mm, "about 15 mm apart"
    assert max([distance(oval_base.stakes.c[i].center, oval_base.stakes.c[(i + 1) % n_oval].center)
                for i in range(n_oval)]) -
           min([distance(oval_base.stakes.c[i].center, oval_base.stakes.c[(i + 1) % n_oval].center)
                for i in range(n_oval)]) <= 0.2 mm, "evenly spaced, straights and curves alike"
    assert distance(oval_base.label, oval_base.stakes) >= 10 mm and
        distance(round_base.label, round_base.ring) >= 5 mm, "labels clear of the holes"
}
