# Parties: a wedding-table napkin ring with the guest's name, cut from 3 mm birch ply. A band
# 45 mm wide that closes into a ring 157 mm round (50 mm across): its two ends lock with a
# flat sliding dovetail (2 tails, 8 mm deep, 10 deg, 0.1 mm clearance in the sockets). A flat
# name panel 50 mm long in the middle of the band carries "EMMA" engraved as filled bold sans
# letters 14 mm tall; between it and each end (10 mm kept stiff at the ends, 2 mm margins) a
# living hinge lets the band bend round.

units mm
thickness 3 mm
import "std/joints.aidl"
import "std/plates.aidl"

param circ = 157 mm, min = 120 mm, max = 220 mm
param band_w = 45 mm, min = 30 mm, max = 60 mm
param joint = 8 mm, min = 5 mm, max = 12 mm
param panel = 50 mm, min = 30 mm, max = 70 mm
param end_keep = 10 mm, min = 8 mm, max = 15 mm
param margin = 2 mm, min = 1 mm, max = 4 mm
hinge_w = (circ - 2 * end_keep - panel - 2 * margin) / 2

solid ring {
    # the band runs from the socket end (x = 0) to the tails' roots (x = circ), and on
    # across the tails' band to circ + joint
    band = Rectangle(bottom_left=(0, -band_w / 2), width=circ + joint, height=band_w)
    tails = dovetail(part="tail", length=band_w, depth=joint, tails=2, angle=10 deg,
                     rotation=-90 deg, cx=circ, cy=0 mm)
    sockets = dovetail(part="socket", length=band_w, depth=joint, tails=2, angle=10 deg,
                       clearance=0.1 mm, rotation=-90 deg, cx=0 mm, cy=0 mm)
    left_hinge = living_hinge(width=hinge_w, height=band_w, cx=end_keep + hinge_w / 2, cy=0 mm)
    right_hinge = living_hinge(width=hinge_w, height=band_w, cx=circ - end_keep - hinge_w / 2,
                               cy=0 mm)
    drawing name {
        t = Text("EMMA", position=(circ / 2, 0), size=14, font="sans:Bold", valign="middle",
                 fill=true)
    }

    # the request's own numbers
    assert band.height == 45 mm, "band 45 mm wide"
    assert band.width - tails.depth == 157 mm, "157 mm round"
    assert tails.depth == 8 mm and len(tails.cut) >= 1, "8 mm dovetail"
    assert right_hinge.bb.left - left_hinge.bb.right == 50 mm + 2 * 2 mm, "50 mm flat name panel between 2 mm margins"
    assert left_hinge.bb.left - band.bb.left == 10 mm, "10 mm stiff at the socket end"
    assert circ - right_hinge.bb.right == 10 mm, "10 mm stiff at the tail end"
    assert name.t.size == 14 mm, "14 mm letters"
    assert name.t.bb.width <= 50 mm, "the name fits its panel"
}
