# Gifts: a two-piece "couple's heart" in 3 mm walnut ply, 102 mm wide and 100 mm tall: two
# R30 lobes centred 21 mm either side of the middle and 10 mm up, the point 60 mm below the
# centre. Split down the middle into two halves locked by a sliding dovetail: 3 tails 10 mm
# deep, 10 deg, over 72 mm of the split line centred 6 mm below the centre, 0.1 mm clearance
# in the sockets.
# (fixed after the first valid program: the joint ended 6.6 mm above the notch and left a
# knife-edge sliver of the right half over the top tail; it now ends 1.4 mm below the notch,
# and the left half reaches across the band only along the joint)
# Names engraved filled in sans Bold 10 mm: "ANNA" on the left half centred at (-25, 5),
# "BEN" on the right half centred at (35, 5).

import "std/joints.aidl"

thickness 3 mm

assembly heart {
    solid left {
        cl = Circle(center=(-21, 10), radius=30, construction=true)
        cr = Circle(center=(21, 10), radius=30, construction=true)
        tip = Point(0, -60)
        keep = Polygon([(-60, -70), (0, -70), (0, -42), (10, -42), (10, 30), (0, 30), (0, 50), (-60, 50)], construction=true)
        a = Intersect(Hull(cl, tip), keep)
        b = Intersect(Hull(cr, tip), keep)
        d = dovetail(part="tail", length=72 mm, depth=10 mm, tails=3, angle=10 deg, rotation=-90 deg, cx=0 mm, cy=-6 mm)
        drawing name {
            t = Text("ANNA", (-25, 5), size=10, valign="middle", font="sans:Bold", fill=true)
        }
    }
    solid right {
        cl = Circle(center=(-21, 10), radius=30, construction=true)
        cr = Circle(center=(21, 10), radius=30, construction=true)
        tip = Point(0, -60)
        keep = Rectangle(corner=(0, -70), opposite=(60, 50), construction=true)
        a = Intersect(Hull(cl, tip), keep)
        b = Intersect(Hull(cr, tip), keep)
        d = dovetail(part="socket", length=72 mm, depth=10 mm, tails=3, angle=10 deg, clearance=0.1 mm, rotation=-90 deg, cx=0 mm, cy=-6 mm)
        drawing name {
            t = Text("BEN", (35, 5), size=10, valign="middle", font="sans:Bold", fill=true)
        }
    }

    assert right.b.bb.right - left.a.bb.left == 102 mm, "102 mm wide"
    assert left.a.bb.top - left.a.bb.bottom == 100 mm, "100 mm tall"
    assert left.cl.radius == 30 mm, "R30 lobes"
    assert left.name.t.size == 10 mm and right.name.t.size == 10 mm, "names 10 mm"
}
