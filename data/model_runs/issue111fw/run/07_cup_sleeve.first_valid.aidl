# REQUEST (gifts): a personalised wooden sleeve for a 12 oz takeaway coffee cup, 3 mm birch
# ply made to bend with a living hinge. The cup is 90 mm across the rim, 60 mm across the
# base and 110 mm tall; the sleeve covers it from 25 mm to 80 mm above the base, so it is
# the flat development of that piece of cone (an annulus sector), plus a 10 mm overlap at one
# end to glue the seam. Hinge: radial slits 2 mm apart (measured on the middle of the band),
# alternately one long slit leaving 3 mm bridges at both edges and two slits from the edges
# leaving a 3 mm bridge in the middle; none within 4 mm of the seam's ends, none over the
# glued overlap, and none on a 34 mm plain panel in the middle of the front, where "MIA" is
# engraved filled (sans bold, 12 mm), horizontal there. Flat part only.
# (after attempt 1: "MIA" at 12 mm is 32.5 mm wide, more than the panel less 2 mm each side;
# the letters are now 12 mm but at most 30 mm wide: the panel is what lets the sleeve bend.)

units mm
thickness 3 mm

cup_top_d = 90 mm
cup_base_d = 60 mm
cup_h = 110 mm
band_low = 25 mm
band_high = 80 mm
overlap = 10 mm
panel_w = 34 mm
margin = 4 mm
pitch = 2 mm
bridge = 3 mm

def d_at(h) = cup_base_d + (cup_top_d - cup_base_d) * h / cup_h
half_angle = atan((cup_top_d - cup_base_d) / 2 / cup_h)
s = sin(half_angle)
r_in = d_at(band_low) / 2 / s
r_out = d_at(band_high) / 2 / s
r_mid = (r_in + r_out) / 2
wrap = 360 deg * s                 # the sector angle that wraps once round the cone
ov = overlap / r_mid * 1 rad
dphi = pitch / r_mid * 1 rad
pm = panel_w / r_mid * 1 rad
mg = margin / r_mid * 1 rad
n_cols = floor((wrap / 2 - mg - pm / 2) / dphi)     # columns each side of the panel
def pt(r, a) = (r * cos(a), r * sin(a))
def col(side, i) = 90 deg + side * (pm / 2 + (i + 0.5) * dphi)

solid sleeve {
    band = Sector(center=(0, 0), radius=r_out, inner_radius=r_in,
                  start_angle=90 deg - wrap / 2 - ov, end_angle=90 deg + wrap / 2)
    cut hinge {
        for side in [-1, 1] {
            for i in range(0, n_cols, 2) {
                long = Line(pt(r_in + bridge, col(side, i)), pt(r_out - bridge, col(side, i)))
            }
            for i in range(1, n_cols, 2) {
                low = Line(pt(r_in - 1 mm, col(side, i)), pt(r_mid - bridge / 2, col(side, i)))
                high = Line(pt(r_mid + bridge / 2, col(side, i)), pt(r_out + 1 mm, col(side, i)))
            }
        }
    }
    drawing name {
        w = Text("MIA", position=(0, r_mid), size=12, font="sans:Bold", valign="middle",
                 fill=true, max_width=30 mm)
    }
}

# the request's numbers
assert abs(d_at(band_low) - (60 mm + 30 mm * 25 / 110)) < 0.001 mm, "cup 66.8 mm across at 25 mm"
# the band's inner edge, without the overlap, is the cup's girth 25 mm up; its outer, 80 mm up
assert abs(wrap / (1 rad) * r_in - pi * (60 mm + 30 mm * 25 / 110)) < 0.1 mm, "girth at 25 mm"
assert abs(wrap / (1 rad) * r_out - pi * (60 mm + 30 mm * 80 / 110)) < 0.1 mm, "girth at 80 mm"
assert abs(ov / (1 rad) * r_mid - 10 mm) < 0.01 mm, "10 mm overlap"
assert sleeve.name.w.bb.width <= 34 mm - 4 mm, "MIA fits the 34 mm panel with 2 mm each side"
assert distance(sleeve.name, sleeve.hinge) >= 2 mm, "no slit within 2 mm of the name"
assert n_cols >= 40, "a hinge of 40 columns or more each side"
