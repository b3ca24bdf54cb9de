# Request: a macaron tower for a wedding dessert table, 4 mm ply. Four round tiers, 240, 190,
# 140 and 90 mm across, 80 mm apart (the lowest 20 mm above the table), each slid down over
# two crossing fins (a cross-halving at the fins' middle) until it rests on the fins'
# shoulders: the fins narrow in steps above each tier, and each tier has a cross-shaped slot
# 0.5 mm longer each way than the fins above its shoulder. The fins stand 320 mm tall on feet
# 200 mm across, with rounded tips. The bottom tier has "EMMA & TOM" engraved over the top of
# its rim and "12 · 06 · 2027" under it (serif outlines), 8 mm tall.

import "std/joints.aidl"

units mm
thickness 4 mm
kerf 0.12 mm

t = 4 mm
height = 320 mm
first = 20 mm     # lowest tier above the table
pitch = 80 mm     # between tiers
diams = [240 mm, 190 mm, 140 mm, 90 mm]
# the fins' half widths: the feet, then above each tier's shoulder
half = [100 mm, 70 mm, 50 mm, 30 mm, 15 mm]

def fin(from_top=true) -> solid {
    body = Polygon([(0, 0), (half[0], 0), (half[0], first), (half[1], first),
                    (half[1], first + pitch), (half[2], first + pitch),
                    (half[2], first + 2 * pitch), (half[3], first + 2 * pitch),
                    (half[3], first + 3 * pitch), (half[4], first + 3 * pitch),
                    (half[4], height), (0, height)], mirror="y")
    Fillet([body.points[10], body.points[12]], 6 mm)
    if from_top {
        x = cross_halving(depth=height / 2, thickness=t, clearance=0.1, cx=0, cy=height)
    } else {
        x = cross_halving(depth=height / 2, thickness=t, clearance=0.1, rotation=180 deg, cx=0, cy=0)
    }
}

def tier(d=240 mm, arm=70 mm) -> solid {
    plate = Circle(center=(0, 0), diameter=d)
    hole cross {
        a = Rectangle(center=(0, 0), width=2 * arm + 1, height=t + 0.2)
        b = Rectangle(center=(0, 0), width=t + 0.2, height=2 * arm + 1)
    }
}

assembly macaron_tower {
    fin_a = fin(from_top=true)
    fin_b = fin(from_top=false)
    RightOf(fin_b, fin_a, gap=10)
    AlignBottom(fin_b, fin_a)

    t1 = tier(d=diams[0], arm=half[1])
    t2 = tier(d=diams[1], arm=half[2])
    t3 = tier(d=diams[2], arm=half[3])
    t4 = tier(d=diams[3], arm=half[4])
    Below(t1, fin_a, gap=10)
    AlignLeft(t1, fin_a)
    RightOf(t2, t1, gap=10)
    AlignBottom(t2, t1)
    RightOf(t3, t2, gap=10)
    AlignBottom(t3, t2)
    Above(t4, t3, gap=10)
    AlignCenterX(t4, t3)

    drawing names {
        ring = Circle(center=(0, 0), radius=104, construction=true)
        top = Text("EMMA & TOM", along=ring, size=8, font="serif")
        date = Text("12 · 06 · 2027", along=ring, size=8, font="serif", flip=true)
    }
    Concentric(names.ring, t1.plate)
    CutInto(names, t1)

    assert t1.plate.diameter == 240 mm and t2.plate.diameter == 190 mm and
        t3.plate.diameter == 140 mm and t4.plate.diameter == 90 mm, "tier sizes"
    assert fin_a.bb.height == 320 mm, "320 tall"
    assert fin_a.bb.width == 200 mm, "feet 200 across"
    # each tier's slot passes the fin above its shoulder and catches on the wider part below
    for k in range(4) {
        assert half[k + 1] + 0.5 mm < half[k], "shoulder under tier"
    }
    assert t1.cross.a.bb.width / 2 - half[1] == 0.5 mm, "0.5 mm longer each way"
    assert first == 20 mm and pitch == 80 mm, "tier heights"
    assert t1.plate.radius - 104 mm >= 8 mm, "names on the rim"
}
