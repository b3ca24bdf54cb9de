# Request (workshop): a wall rack for my three tape measures (3 m, 5 m, 8 m), 6 mm birch ply.
# Back plate 300 x 90 mm, corners r6, hung on two screws by keyholes (9 mm head, 4.5 mm shank,
# 12 mm long, pointing up), 240 mm apart, 20 mm above the plate's centre line.
# Three tongues 36 mm wide stick straight out 70 mm from the plate's face (front corners r8),
# 95 mm apart centre to centre, 15 mm below the centre line; each tongue is glued into the plate
# with two 10 mm tabs through mortises. A tape's belt clip slides onto a tongue.
# The size of each tape ("3 m", "5 m", "8 m") engraved above its tongue, 7 mm letters.

import "std/joints.aidl"
import "std/plates.aidl"

thickness 6 mm

ply = 6 mm
reach = 70 mm      # how far a tongue stands out from the plate's face
pitch = 95 mm
row_y = -15 mm

def tongue() -> solid {
    # the tabs' tips at y = 0 (flush with the plate's back), the tongue toward -y
    body = RoundedRectangle(center=(0, -(reach + ply) / 2), width=36, height=reach + ply,
                            corner_radii=[0, 0, 8, 8])
    t = tab_and_slot(part="tab", length=36 mm, thickness=ply, tabs=2, tab=10 mm, screw=0,
                     cx=0 mm, cy=0 mm)
}

assembly rack {
    solid plate {
        body = RoundedRectangle(center=(0, 0), width=300, height=90, corner_radius=6)
        for i in range(3) {
            m = tab_and_slot(part="slot", length=36 mm, thickness=ply, tabs=2, tab=10 mm,
                             screw=0, cx=(i - 1) * pitch, cy=row_y)
        }
        kl = keyhole(head=9 mm, slot_width=4.5 mm, length=12 mm, direction=90 deg,
                     cx=-120 mm, cy=20 mm)
        kr = keyhole(head=9 mm, slot_width=4.5 mm, length=12 mm, direction=90 deg,
                     cx=120 mm, cy=20 mm)
        drawing sizes {
            for i in range(3) {
                lab = Text(["3 m", "5 m", "8 m"][i], ((i - 1) * pitch, row_y + 14), size=7)
            }
        }
    }
    # the plate on the wall: its face in the x-z plane, the front face at y = -6
    Place(plate, position=(0, 0, 0), rotation=(90 deg, 0, 0))

    for i in range(3) {
        tg = tongue()
        # flat, its tabs through the plate's mortise i
        Place(tg, position=((i - 1) * pitch, 0, row_y - ply / 2), rotation=(0, 0, 0))
    }
    # on the sheet: the tongues in a row under the plate
    Below(tg[0], plate, gap=8)
    AlignLeft(tg[0], plate)
    RightOf(tg[1], tg[0], gap=8)
    RightOf(tg[2], tg[1], gap=8)
    AlignTop(tg[1], tg[0])
    AlignTop(tg[2], tg[0])

    assert len(tg) == 3, "three tapes"
    assert plate.body.bb.width == 300 mm and plate.body.bb.height == 90 mm, "plate 300 x 90"
    assert plate.kr.head_hole.center.x - plate.kl.head_hole.center.x == 240 mm, "keyholes 240 apart"
    assert plate.m[1].bb.center_x - plate.m[0].bb.center_x == 95 mm, "tongues 95 apart"
    assert tg[0].body.bb.height - ply == 70 mm, "tongue stands out 70"
    assert tg[0].body.bb.width == 36 mm, "tongue 36 wide"
}
