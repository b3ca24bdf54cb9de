# Request (home): "Bar pulls for my kitchen drawers. Standard 128 mm screw centres, the pull
# 148 mm long overall, standing 30 mm off the drawer front, the grip bar 14 mm deep (so the
# finger opening under it is 16 mm high), top corners rounded 8 mm, the opening's top corners
# rounded 5 mm. Laminated from three layers of 6 mm birch ply (18 mm wide): the two outer
# layers plain, the middle layer with an M3 T-slot in each foot so an M3 x 30 screw from inside
# the drawer pulls on a captive nut: slot 14 mm long, nut 8 mm in from the drawer face."

import "std/fasteners.aidl"

thickness 6 mm

param centres = 128 mm, min = 64 mm, max = 224 mm
param standoff = 30 mm, min = 25 mm, max = 40 mm
param grip = 14 mm, min = 10 mm, max = 18 mm
param foot = 20 mm, min = 16 mm, max = 26 mm

length = centres + foot

def pull_outline(l=148 mm, h=30 mm, g=14 mm, f=20 mm) -> solid {
    body = RoundedRectangle(center=(0, h / 2), width=l, height=h, corner_radii=[8, 8, 0, 0])
    # the finger opening between the feet; runs 1 mm past the drawer face so it opens cleanly
    hole opening {
        o = RoundedRectangle(center=(0, (h - g - 1) / 2), width=l - 2 * f, height=h - g + 1,
                             corner_radii=[5, 5, 0, 0])
    }
}

assembly pull {
    outer_a = pull_outline(l=length, h=standoff, g=grip, f=foot)

    solid middle {
        core = pull_outline(l=length, h=standoff, g=grip, f=foot)
        # mouths on the drawer face (y = 0) at the screw centres, running up into the feet
        left_slot = t_slot(size=3, length=14 mm, nut_depth=8 mm, rotation=180 deg,
                           cx=-centres / 2, cy=0 mm)
        right_slot = t_slot(size=3, length=14 mm, nut_depth=8 mm, rotation=180 deg,
                            cx=centres / 2, cy=0 mm)
    }

    outer_b = pull_outline(l=length, h=standoff, g=grip, f=foot)

    # flat on the sheet: one above the other, 5 mm apart
    Above(middle, outer_a, gap=5)
    Above(outer_b, middle, gap=5)
    AlignCenterX(middle, outer_a)
    AlignCenterX(outer_b, middle)

    # assembled: laminated, 6 mm each
    Place(outer_a, position=(0, 0, 0))
    Place(middle, position=(0, 0, 6))
    Place(outer_b, position=(0, 0, 12))

    # the request's numbers
    assert outer_a.body.bb.width == 148 mm, "148 mm long"
    assert outer_a.body.bb.height == 30 mm, "stands 30 mm off the drawer"
    assert outer_a.body.bb.top - outer_a.opening.o.bb.top == 14 mm, "grip 14 mm deep"
    assert middle.right_slot.slot.center.x - middle.left_slot.slot.center.x == 128 mm,
        "128 mm screw centres"
    assert middle.left_slot.slot.bb.height == 14 mm, "slot 14 mm long"
}
