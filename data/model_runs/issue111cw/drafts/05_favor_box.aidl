# Request (parties): a wedding favour "pillow box" cut and scored from 350 gsm card (0.4 mm).
# Closed it is 80 mm wide and 120 mm tall. The flat blank is two 80 x 120 mm panels side by
# side plus a 12 mm glue flap (tapered 10 mm at its ends) on the right. Each panel end has a
# curved flap bulging 20 mm out (an arc through the panel corners), and is scored along the
# mirror arc bulging 20 mm into the panel, so the ends fold in as a pillow; the two panel folds
# and the glue flap fold are scored straight. The front (left) panel has a heart-shaped window
# 34 mm wide, "MAYA & SAM" engraved above it in filled serif letters 7 mm high, and the date
# "14.06.2027" in 5 mm single-stroke letters below it.

# FIX after the first valid program: W0505 (real) said fold[2] lay 100% off the material at
# x = 240: my slip, a blank has two straight folds (x = 80 between the panels, x = 160 at the
# glue flap), not three; the request's "two panel folds and the glue flap fold" miscounted.

units mm
thickness 0.4 mm
min_wall 0.3 mm

panel_w = 80 mm
panel_h = 120 mm
bulge = 20 mm
flap = 12 mm
flap_taper = 10 mm
# the end arcs: chord panel_w, sagitta bulge
arc_r = (panel_w * panel_w / 4 + bulge * bulge) / (2 * bulge)

solid blank {
    for k in range(2) {
        panel = Rectangle(bottom_left=(k * panel_w, 0), width=panel_w, height=panel_h)
        top_flap = Intersect(Circle(center=(k * panel_w + panel_w / 2, panel_h + bulge - arc_r),
                                    radius=arc_r),
                             Rectangle(bottom_left=(k * panel_w, panel_h), width=panel_w,
                                       height=bulge))
        bottom_flap = Intersect(Circle(center=(k * panel_w + panel_w / 2, arc_r - bulge),
                                       radius=arc_r),
                                Rectangle(bottom_left=(k * panel_w, -bulge), width=panel_w,
                                          height=bulge))
    }
    glue = Polygon([(2 * panel_w, 0), (2 * panel_w + flap, flap_taper),
                    (2 * panel_w + flap, panel_h - flap_taper), (2 * panel_w, panel_h)])

    drawing scores {
        for k in range(2) {   # FIX: was range(3)
            fold = Line((k * panel_w + panel_w, 0), (k * panel_w + panel_w, panel_h))
        }
        for k in range(2) {
            top_score = Arc(start=(k * panel_w, panel_h),
                            through=(k * panel_w + panel_w / 2, panel_h - bulge),
                            end=(k * panel_w + panel_w, panel_h))
            bottom_score = Arc(start=(k * panel_w, 0),
                               through=(k * panel_w + panel_w / 2, bulge),
                               end=(k * panel_w + panel_w, 0))
        }
    }

    hole heart_window {
        lobe_l = Hull(Circle(center=(panel_w / 2 - 8, 57), radius=9), Point(panel_w / 2, 36))
        lobe_r = Hull(Circle(center=(panel_w / 2 + 8, 57), radius=9), Point(panel_w / 2, 36))
    }

    drawing names {
        n = Text("MAYA & SAM", position=(panel_w / 2, 86), size=7, font="serif", fill=true)
        d = Text("14.06.2027", position=(panel_w / 2, 24), size=5)
    }

    assert panel[0].bb.width == 80 mm and panel[0].bb.height == 120 mm, "80 x 120 panels"
    assert len(panel) == 2, "two panels"
    assert len(scores.fold) == 2, "FIX: two straight folds"
    assert glue.bb.width == 12 mm, "12 mm glue flap"
    assert top_flap[0].bb.height == 20 mm, "ends bulge 20 mm"
    assert panel_h - scores.top_score[0].through.y == 20 mm, "score bulges 20 mm in"
    assert heart_window.bb.width == 34 mm, "heart 34 mm wide"
    assert names.n.size == 7 mm and names.d.size == 5 mm, "letter sizes"
    assert names.n.bb.bottom > heart_window.bb.top, "names above the heart"
    assert names.d.bb.top < heart_window.bb.bottom, "date below the heart"
    assert names.n.bb.left > 0 and names.n.bb.right < panel_w, "names on the front panel"
}
