# Request (parties): a birthday-party tiara for my daughter, 3 mm birch ply. A band 400 x 20 mm
# with round ends; in the middle a three-peaked crest: the centre peak's tip 77 mm above the
# band's bottom edge, the side peaks' tips 53 mm, 38 mm either side of the centre, all tips
# rounded and the valleys between the peaks softened (3 mm). A 5-point star (26 mm across its
# tips) cut out of the centre peak, a 10 mm round window in each side peak, her name "SOPHIE"
# engraved filled (serif bold, 8 mm) at the foot of the crest. Living hinges 100 mm long in
# the band either side of the crest (starting 70 mm from the centre) so it bends round her
# head, and a 3 x 12 mm upright slot 12 mm in from each end for the elastic.

import "std/plates.aidl"

thickness 3 mm

band_len = 400 mm
band_h = 20 mm

solid tiara {
    band = Slot(center=(0, band_h / 2), length=band_len, width=band_h)

    solid crest {
        mid = Hull(Circle(center=(0, 70 mm), radius=7 mm),
                   Rectangle(center=(0, band_h / 2), width=90 mm, height=band_h))
        left = Hull(Circle(center=(-38 mm, 48 mm), radius=5 mm),
                    Rectangle(center=(-38 mm, band_h / 2), width=50 mm, height=band_h))
        right = Hull(Circle(center=(38 mm, 48 mm), radius=5 mm),
                     Rectangle(center=(38 mm, band_h / 2), width=50 mm, height=band_h))
        Fillet(3 mm)
    }

    hole star {
        s = Star(center=(0, 45 mm), points=5, outer_radius=13 mm, inner_radius=5.5 mm)
    }
    hole windows {
        l = Circle(center=(-38 mm, 32 mm), diameter=10 mm)
        r = Circle(center=(38 mm, 32 mm), diameter=10 mm)
    }
    hole elastic {
        l = Slot(center=(-band_len / 2 + 12 mm, band_h / 2), length=12 mm, width=3 mm,
                 rotation=90 deg)
        r = Slot(center=(band_len / 2 - 12 mm, band_h / 2), length=12 mm, width=3 mm,
                 rotation=90 deg)
    }

    left_hinge = living_hinge(width=100 mm, height=band_h, pitch=2 mm, cut=9 mm, bridge=2 mm,
                              cx=-120 mm, cy=band_h / 2)
    right_hinge = living_hinge(width=100 mm, height=band_h, pitch=2 mm, cut=9 mm, bridge=2 mm,
                               cx=120 mm, cy=band_h / 2)

    drawing name {
        n = Text("SOPHIE", position=(0, 9 mm), size=8 mm, font="serif:Bold", valign="middle",
                 fill=true)
    }

    assert band.length == 400 mm and band.width == 20 mm, "band 400 x 20"
    assert abs(crest.bb.top - band.bb.bottom - 77 mm) < 0.01 mm, "centre peak 77 mm up"
    assert abs(crest.left.bb.top - band.bb.bottom - 53 mm) < 0.01 mm, "side peaks 53 mm up"
    assert star.s.outer_radius * 2 == 26 mm, "star 26 mm across its tips"
    assert windows.l.diameter == 10 mm, "10 mm windows"
    assert name.n.size == 8 mm, "name 8 mm"
    assert left_hinge.width == 100 mm and right_hinge.width == 100 mm, "hinges 100 mm"
    assert right_hinge.bb.center_x - 50 mm == 70 mm, "hinge starts 70 mm from the centre"
    assert band.bb.right - elastic.r.center.x == 12 mm, "elastic slot 12 mm in"
    assert elastic.r.length == 12 mm and elastic.r.width == 3 mm, "elastic slot 3 x 12"
}
