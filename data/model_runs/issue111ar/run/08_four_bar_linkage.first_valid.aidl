# Request (science): a classroom four-bar linkage (crank-rocker) kit, 3 mm clear acrylic, joined
# with M4 bolts (4.2 mm holes). Ground plate 200 x 70 mm, 5 mm corner radii, with the two ground
# pivots 120 mm apart, centred, 15 mm above the plate's centre; four 4.2 mm screw holes 8 mm in
# from each corner to fix it to a board; "FOUR-BAR LINKAGE" (5 mm single stroke) centred 20 mm
# below the plate's centre and "s + l <= p + q" (3.5 mm) 8 mm under it. Links 14 mm wide with
# round ends and a 4.2 mm hole at each end's centre: a crank of 40 mm centres, a rocker of 90 mm;
# the coupler is a 14 mm wide triangular plate (hull of three 14 mm circles): its two pivots
# 130 mm apart and an 8 mm pen hole 25 mm off their line, midway. Each link engraved with its
# name and length ("CRANK 40", 4 mm, at most its centres less 12 mm wide) between its holes.
# Grashof must hold (shortest + longest <= the other two) so the crank turns all the way round.
# Parts laid flat, 6 mm apart.

thickness 3 mm

param ground = 120 mm, min = 100 mm, max = 150 mm
param crank_c = 40 mm, min = 25 mm, max = 60 mm
param coupler_c = 130 mm, min = 100 mm, max = 160 mm
param rocker_c = 90 mm, min = 60 mm, max = 120 mm
bolt = 4.2 mm
w = 14 mm

assert min(ground, crank_c, coupler_c, rocker_c) + max(ground, crank_c, coupler_c, rocker_c) <= ground + crank_c + coupler_c + rocker_c - min(ground, crank_c, coupler_c, rocker_c) - max(ground, crank_c, coupler_c, rocker_c), "Grashof: s + l <= p + q"
assert min(ground, crank_c, coupler_c, rocker_c) == crank_c, "the crank is the shortest link (crank-rocker)"

def link(centres=40 mm, label="CRANK") -> solid {
    bar = Slot(center=(centres / 2, 0), length=centres + w, width=w)
    hole pivots {
        a = Circle(center=(0, 0), diameter=bolt)
        b = Circle(center=(centres, 0), diameter=bolt)
    }
    drawing name {
        t = Text(label + " " + str(round(centres / 1 mm)), (centres / 2, 0), size=4,
                 valign="middle", max_width=centres - 12 mm)
    }
}

assembly linkage {
    solid base {
        body = RoundedRectangle(center=(0, 0), width=200, height=70, corner_radius=5)
        hole pivots {
            a = Circle(center=(-ground / 2, 15), diameter=bolt)
            b = Circle(center=(ground / 2, 15), diameter=bolt)
        }
        hole screw {
            c = Circle(center=(-92, -27), diameter=bolt)
        }
        screws = CornerPattern(screw, body, inset=8)
        drawing title {
            name = Text("FOUR-BAR LINKAGE", (0, -20), size=5, valign="middle")
            rule = Text("s + l <= p + q", (0, -28), size=3.5, valign="middle")
        }
        Fixed(body)
    }
    crank = link(centres=crank_c, label="CRANK")
    rocker = link(centres=rocker_c, label="ROCKER")
    solid coupler {
        e0 = Circle(center=(0, 0), diameter=w)
        e1 = Circle(center=(coupler_c, 0), diameter=w)
        e2 = Circle(center=(coupler_c / 2, 25), diameter=w)
        plate = Hull(e0, e1, e2)
        hole pivots {
            a = Circle(center=(0, 0), diameter=bolt)
            b = Circle(center=(coupler_c, 0), diameter=bolt)
        }
        hole pen {
            c = Circle(center=(coupler_c / 2, 25), diameter=8)
        }
        drawing name {
            t = Text("COUPLER " + str(round(coupler_c / 1 mm)), (coupler_c / 2, 0), size=4,
                     valign="middle", max_width=coupler_c - 12 mm)
        }
    }

    Below(coupler, base, gap=6)
    AlignLeft(coupler, base)
    Below(crank, coupler, gap=6)
    AlignLeft(crank, coupler)
    RightOf(rocker, crank, gap=6)
    AlignTop(rocker, crank)

    assert abs(base.body.width - 200 mm) < 0.01 mm and abs(base.body.height - 70 mm) < 0.01 mm, "plate 200 x 70"
    assert abs(base.pivots.b.center.x - base.pivots.a.center.x - 120 mm) < 0.01 mm, "ground pivots 120 apart"
    assert abs(base.pivots.a.center.y - base.body.center.y - 15 mm) < 0.01 mm, "15 above the centre"
    assert len(base.screws) == 4, "four screw holes"
    assert abs(base.screws[2].c.center.x - (base.body.bb.right - 8 mm)) < 0.01 mm and abs(base.screws[2].c.center.y - (base.body.bb.top - 8 mm)) < 0.01 mm, "8 in from the corner"
    assert abs(crank.pivots.b.center.x - crank.pivots.a.center.x - 40 mm) < 0.01 mm, "crank 40"
    assert abs(rocker.pivots.b.center.x - rocker.pivots.a.center.x - 90 mm) < 0.01 mm, "rocker 90"
    assert abs(coupler.pivots.b.center.x - coupler.pivots.a.center.x - 130 mm) < 0.01 mm, "coupler 130"
    assert abs(coupler.pen.c.center.y - coupler.pivots.a.center.y - 25 mm) < 0.01 mm, "pen 25 off the line"
    assert abs(crank.bar.width - 14 mm) < 0.01 mm, "14 mm links"
    assert crank.name.bb.left > crank.pivots.a.bb.right and crank.name.bb.right < crank.pivots.b.bb.left, "crank label between its holes"
}
