# Request: a tinder box for my camping fire kit (ferro rod, striker, char cloth, cotton
# wool), cut from 3 mm birch ply, finger-jointed with a sliding lid.
# - Outside 140 x 70 x 45 mm, 10 mm fingers, 0.3 mm lid clearance.
# - In the lid: a 25 x 10 mm finger-pull slot across the lid, its centre 12 mm in from the
#   lid's front edge (the edge that slides out first), centred side to side.
# - Engraved on the lid, filled: a flame 30 mm tall and 18 mm wide with a sharp tip, and the
#   word "TINDER" in bold capitals 9 mm tall beside it; the group centred side to side,
#   8 mm behind the lid's centre (away from the pull), at least 4 mm from the pull.

import "std/boxes.aidl"

thickness 3 mm

assembly tinder_box {
    box = sliding_lid_box(length=140 mm, width=70 mm, height=45 mm, thickness=3 mm,
                          finger=10 mm, clearance=0.3 mm)

    hole pull {
        s = Slot(center=(0, 0), length=25, width=10)
    }
    AlignCenterX(pull, box.lid)
    pull.s.center.y == box.lid.bb.bottom + 12 mm
    CutInto(pull, box.lid)

    drawing mark {
        flame = Spline([(-30, 15), (-26, 6), (-21, -3), (-22.5, -10), (-30, -15), (-37.5, -10),
                        (-39, -3), (-35, 4), (-33, 2), (-32, 8)], closed=true, corners=[0],
                       fill=true)
        word = Text("TINDER", position=(-18, 0), size=9, anchor="start", valign="middle",
                    font="sans:Bold", fill=true)
    }
    AlignCenterX(mark, box.lid)
    mark.bb.center_y == box.lid.bb.center_y + 8 mm
    CutInto(mark, box.lid)

    assert box.length == 140 mm and box.width == 70 mm and box.height == 45 mm, "140 x 70 x 45"
    assert pull.s.length == 25 mm and pull.s.width == 10 mm, "pull 25 x 10"
    assert pull.s.center.y - box.lid.bb.bottom == 12 mm, "pull 12 mm from the front edge"
    assert mark.flame.points[0].y - mark.flame.points[4].y == 30 mm, "flame 30 tall"
    assert mark.flame.points[2].x - mark.flame.points[6].x == 18 mm, "flame 18 wide"
    assert distance(mark, pull) >= 4 mm, "engraving 4 mm clear of the pull"
    assert mark.bb.left >= box.lid.bb.left + 5 mm and mark.bb.right <= box.lid.bb.right - 5 mm, "engraving on the lid"
}
