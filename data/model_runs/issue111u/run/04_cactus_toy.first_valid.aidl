# Toys: a stand-up 3D cactus from two identical 3 mm plywood silhouettes slotted into each other
# crosswise (cross_halving, 0.1 mm clearance). Each silhouette: trunk 30 mm wide x 120 mm tall,
# flat bottom, round top (R15); left arm 14 mm thick leaving the trunk 40 mm up, reaching out to
# 35 mm left of the trunk's centre line then rising to 85 mm up (round tip); right arm 12 mm thick
# leaving 60 mm up, out to 35 mm right, rising to 95 mm up; outer elbows rounded. Piece A is
# slotted 60 mm down from the top of the trunk, piece B 60 mm up from the bottom (60 + 60 = 120).

import "std/joints.aidl"

thickness 3 mm

param t = 3 mm, min = 2 mm, max = 6 mm
param height = 120 mm, min = 80 mm, max = 200 mm

def cactus(from_top=true) -> solid {
    trunk = RoundedRectangle(bottom_left=(-15, 0), width=30, height=height,
                             corner_radii=[15, 15, 0, 0])
    l_bar = Rectangle(bottom_left=(-35, 40), width=25, height=14)
    l_up = RoundedRectangle(bottom_left=(-35, 40), width=14, height=45, corner_radii=[7, 7, 0, 0])
    r_bar = Rectangle(bottom_left=(10, 60), width=25, height=12)
    r_up = RoundedRectangle(bottom_left=(23, 60), width=12, height=35, corner_radii=[6, 6, 0, 0])
    l_elbow = Point(-35, 40, construction=true)
    r_elbow = Point(35, 60, construction=true)
    Fillet(l_elbow, 7)
    Fillet(r_elbow, 6)
    if from_top {
        j = cross_halving(depth=height / 2, thickness=t, clearance=0.1 mm, rotation=0 deg,
                          cx=0 mm, cy=height)
    } else {
        j = cross_halving(depth=height / 2, thickness=t, clearance=0.1 mm, rotation=180 deg,
                          cx=0 mm, cy=0 mm)
    }
}

assembly cactus_kit {
    a = cactus(from_top=true)
    b = cactus(from_top=false)
    RightOf(b, a, gap=10)
    AlignBottom(b, a)

    assert a.trunk.bb.width == 30 mm and a.trunk.bb.height == 120 mm, "trunk 30 x 120"
    assert a.bb.width == 70 mm, "arms out 35 either side"
    assert a.l_up.bb.top - a.trunk.bb.bottom == 85 mm, "left arm up to 85"
    assert a.r_up.bb.top - a.trunk.bb.bottom == 95 mm, "right arm up to 95"
    assert a.j.cut.bb.height == 60 mm and b.j.cut.bb.height == 60 mm, "slots 60 + 60"
    assert a.j.cut.bb.top == a.trunk.bb.top, "A slotted from the top"
    assert b.j.cut.bb.bottom == b.trunk.bb.bottom, "B slotted from the bottom"
}
