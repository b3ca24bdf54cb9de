# Request (home): a wall-mounted ironing-board hanger in 6 mm birch ply. A back plate
# 140 wide x 320 tall with R12 corners, screwed to the wall with three M4 countersunk
# screws (9 mm heads) on the centre line: 25 mm from the top, at the middle, 25 mm from
# the bottom. Two hooks stand out of the plate 90 mm apart (centre to centre), each
# reaching 100 mm out from the wall: a 30 mm deep arm with a 25 mm upturned lip 15 mm
# thick at its end, and a back post 60 mm tall glued into the plate with two 15 mm
# tenons through mortises. The hooks' tops are 60 mm below the plate's top. The word
# IRONING engraved filled in serif, 16 mm capitals, centred 75 mm below the plate's
# centre. Three parts; they slot together.

import "std/joints.aidl"
import "std/fasteners.aidl"

thickness 6 mm

param reach = 100 mm, min = 70 mm, max = 140 mm

# one hook, seen from the side: x out from the wall face (0), y up (0 = the arm's top);
# the post's back edge stands 6 mm behind the wall face: the tenons' tips
def hook(reach=100 mm) -> solid {
    body = Polygon([(-6, -60), (20, -60), (50, -30), (reach, -30), (reach, 25),
                    (reach - 15, 25), (reach - 15, 0), (-6, 0)])
    tenons = tab_and_slot(part="tab", length=60 mm, thickness=6 mm, tabs=2, tab=15 mm,
                          screw=0, rotation=90 deg, cx=-6 mm, cy=-30 mm)
    Fillet([body.points[2], body.points[6]], 8)
    Fillet([body.points[1], body.points[3], body.points[4], body.points[5]], 4)
}

assembly hanger {
    solid plate {
        body = RoundedRectangle(center=(0, 0), width=140, height=320, corner_radius=12)
        # mortises for the two hooks: posts span 40..100 (hook top 60 below the plate top)
        left_mortise = tab_and_slot(part="slot", length=60 mm, thickness=6 mm, tabs=2,
                                    tab=15 mm, screw=0, rotation=90 deg, cx=-45 mm, cy=70 mm)
        right_mortise = tab_and_slot(part="slot", length=60 mm, thickness=6 mm, tabs=2,
                                     tab=15 mm, screw=0, rotation=90 deg, cx=45 mm, cy=70 mm)
        top_screw = clearance_hole(size=4, cx=0 mm, cy=135 mm)
        mid_screw = clearance_hole(size=4, cx=0 mm, cy=0 mm)
        low_screw = clearance_hole(size=4, cx=0 mm, cy=-135 mm)
        Countersink([top_screw, mid_screw, low_screw], diameter=9 mm)
        drawing label {
            word = Text("IRONING", position=(0, -75), size=16, font="serif",
                        valign="middle", fill=true)
        }
    }
    left_hook = hook(reach=reach)
    right_hook = hook(reach=reach)

    # flat on the sheet: the hooks beside the plate
    RightOf(left_hook, plate, gap=10)
    AlignTop(left_hook, plate)
    RightOf(right_hook, left_hook, gap=10)
    AlignTop(right_hook, left_hook)

    # in 3D: the plate stands with its front face toward -y, the hooks stick out to the
    # front through it (their tenon tips at the plate's back face, y = 0)
    Place(plate, position=(0, 0, 0), face="front", up="up")
    Place(left_hook, position=(-42, -6, 100), face="left", up="up")
    Place(right_hook, position=(48, -6, 100), face="left", up="up")

    assert plate.body.bb.width == 140 mm, "plate 140 wide"
    assert plate.body.bb.height == 320 mm, "plate 320 tall"
    assert plate.right_mortise.bb.center_x - plate.left_mortise.bb.center_x == 90 mm,
        "hooks 90 mm apart"
    assert plate.body.bb.top - (plate.left_mortise.bb.center_y + 60 mm / 2) == 60 mm,
        "hook tops (the 60 mm post's top) 60 below the top"
    assert plate.body.bb.top - plate.top_screw.c.center.y == 25 mm, "top screw 25 from the top"
    assert plate.low_screw.c.center.y - plate.body.bb.bottom == 25 mm, "low screw 25 up"
    assert left_hook.body.bb.right - (left_hook.body.bb.left + 6 mm) == 100 mm,
        "hooks reach 100 out from the wall"
    assert left_hook.body.bb.height == 60 mm + 25 mm, "post 60 tall, lip 25 above the arm"
    assert plate.body.bb.center_y - plate.label.word.position.y == 75 mm, "label 75 below centre"
}
