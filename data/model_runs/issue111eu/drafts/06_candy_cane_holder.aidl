# Request: a Christmas candy cane holder for the hall table, 4 mm birch ply, glued. Two
# five-pointed stars (outer radius 75, inner 45, tips rounded R8, first tip pointing back),
# a base and a top, held 70 mm apart (face to face) by a central column of two 50 mm wide
# plates crossed by a cross halving (one slotted from the top, one from the bottom, 4.1 mm
# wide), each plate with two 10 mm tenons top and bottom through mortises in the stars
# (0.1 mm over). The top star has ten 8 mm holes for canes to stand crook up, resting on the
# base: one near each tip 58 mm from the centre, one in each notch 35 mm from the centre;
# every hole at least 4 mm from the star's edge and from the column. Laid out flat to cut,
# 8 mm apart; assembled for a look.

import "std/joints.aidl"

thickness 4 mm

t = 4 mm
gap_h = 70 mm     # between the stars, face to face
col_w = 50 mm
R_out = 75 mm
R_in = 45 mm
tip_hole_r = 58 mm
notch_hole_r = 35 mm
cane = 8 mm

def star_plate(holes=false) -> solid {
    s = Star(center=(0, 0), points=5, outer_radius=R_out, inner_radius=R_in, tip_radius=8)
    mortise_a = tab_and_slot(part="slot", length=col_w, thickness=t, tabs=2, tab=10 mm,
                             screw=0, clearance=0.1 mm, cx=0, cy=0)
    mortise_b = tab_and_slot(part="slot", length=col_w, thickness=t, tabs=2, tab=10 mm,
                             screw=0, clearance=0.1 mm, rotation=90 deg, cx=0, cy=0)
    if holes {
        hole tip_hole { c = Circle(center=(0, tip_hole_r), diameter=cane) }
        hole notch_hole { c = Circle(center=polar((0, 0), notch_hole_r, 90 deg + 36 deg), diameter=cane) }
        tips = CircularPattern(tip_hole, 5, (0, 0))
        notches = CircularPattern(notch_hole, 5, (0, 0))
    }
}

# a column plate: halving slot from the top (from_top) or from the bottom
def column_plate(from_top=true) -> solid {
    body = Rectangle(bottom_left=(-col_w / 2, -t), width=col_w, height=gap_h + 2 * t)
    low = tab_and_slot(part="tab", length=col_w, thickness=t, tabs=2, tab=10 mm, screw=0,
                       rotation=180 deg, cx=0, cy=-t)
    high = tab_and_slot(part="tab", length=col_w, thickness=t, tabs=2, tab=10 mm, screw=0,
                        rotation=0 deg, cx=0, cy=gap_h + t)
    if from_top {
        halving = cross_halving(depth=gap_h / 2, thickness=t, clearance=0.1 mm, cx=0, cy=gap_h)
    } else {
        halving = cross_halving(depth=gap_h / 2, thickness=t, clearance=0.1 mm,
                                rotation=180 deg, cx=0, cy=0)
    }
}

assembly holder {
    base = star_plate()
    top = star_plate(holes=true)
    col_a = column_plate(from_top=true)
    col_b = column_plate(from_top=false)

    # flat, to cut
    RightOf(top, base, gap=8)
    AlignTop(top, base)
    RightOf(col_a, top, gap=8)
    AlignTop(col_a, base)
    Below(col_b, col_a, gap=8)
    AlignLeft(col_b, col_a)

    # assembled: base on z = 0, the column's plates along x (a) and y (b)
    Place(base, position=(0, 0, 0), face="up")
    Place(top, position=(0, 0, t + gap_h), face="up")
    Place(col_a, position=(0, t / 2, t), face="front")
    Place(col_b, position=(-t / 2, 0, t), face="right")

    # the request's numbers
    assert top.s.outer_radius == 75 mm and top.s.inner_radius == 45 mm, "star 75 / 45"
    assert len(top.tips) + len(top.notches) == 10, "ten cane holes"
    assert top.tip_hole.c.diameter == 8 mm, "8 mm holes"
    assert distance(top.tip_hole.c.center, top.s.center) == 58 mm, "tip holes 58 out"
    assert distance(top.notch_hole.c.center, top.s.center) == 35 mm, "notch holes 35 out"
    assert col_a.body.bb.height - 2 * t == 70 mm, "stars 70 apart"
    assert col_a.body.bb.width == 50 mm, "column plates 50 wide"
    assert col_a.halving.cut.bb.height + col_b.halving.cut.bb.height == gap_h, "halvings meet"
    assert notch_hole_r - cane / 2 - col_w / 2 >= 4 mm, "notch holes clear of the column"
    # a tip hole's clearance to the star's side: the side from the tip to the next notch
    assert distance(top.tip_hole.c.center, top.s.edges[0]) - cane / 2 >= 4 mm, "tip holes 4 mm in"
    assert R_in - notch_hole_r - cane / 2 >= 4 mm, "notch holes 4 mm in"
}
