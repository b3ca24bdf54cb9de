# Request (music): a neck rest for restringing guitars, 6 mm ply, three parts that slot
# together without glue. Cradle: 170 x 80 mm, top corners R15; a U for the neck cut from the
# middle of the top edge, a circle R32 centred on the top edge (32 mm deep), its two top
# corners rounded R5; a low arch between the feet, half an ellipse 70 wide and 14 high in the
# middle of the bottom edge; two cross-halving slots 15 mm up from the bottom edge, 60 mm
# either side of the middle (0.2 mm clearance); engraved "NECK REST" on each shoulder, size 5.
# Two feet 110 x 30 mm, top corners R6, each with a cross-halving slot 15 mm down from the
# middle of its top edge, so the feet and the cradle stand flush on the bench.

import "std/joints.aidl"

thickness 6 mm
mat = 6 mm
param neck_r = 32 mm, min = 22 mm, max = 40 mm

def foot() -> solid {
    body = RoundedRectangle(center=(0, 0), width=110, height=30, corner_radii=[6, 6, 0, 0])
    halving = cross_halving(depth=15 mm, thickness=mat, clearance=0.2 mm, cx=0 mm, cy=15 mm)
}

assembly neck_rest {
    solid cradle {
        body = RoundedRectangle(bottom_left=(-85, 0), width=170, height=80,
                                corner_radii=[15, 15, 0, 0])
        hole u {
            c = Circle(center=(0, 80), radius=neck_r)
        }
        hole arch {
            e = Ellipse(center=(0, 0), rx=35, ry=14)
        }
        slot_l = cross_halving(depth=15 mm, thickness=mat, clearance=0.2 mm, rotation=180 deg,
                               cx=-60 mm, cy=0 mm)
        slot_r = cross_halving(depth=15 mm, thickness=mat, clearance=0.2 mm, rotation=180 deg,
                               cx=60 mm, cy=0 mm)
        Fillet([body.top, u.c], 5)
        drawing label {
            left = Text("NECK REST", position=(-58, 52), size=5, valign="middle")
            right = Text("NECK REST", position=(58, 52), size=5, valign="middle")
        }
        assert body.bb.width == 170 mm and body.bb.height == 80 mm, "cradle 170 x 80"
        assert body.bb.top - u.c.center.y == 0 mm and u.c.radius == 32 mm, "U of R32 on the top edge"
        assert slot_r.cx - slot_l.cx == 120 mm, "slots 60 mm either side"
        assert arch.e.rx * 2 == 70 mm and arch.e.ry == 14 mm, "arch 70 x 14"
    }
    foot_l = foot()
    foot_r = foot()
    Below(foot_l, cradle, gap=8)
    AlignLeft(foot_l, cradle)
    RightOf(foot_r, foot_l, gap=8)
    AlignTop(foot_r, foot_l)
    assert foot_l.halving.depth + cradle.slot_l.depth == foot_l.body.bb.height,
        "halvings add up to the foot's height: flush on the bench"
    assert foot_l.body.bb.width == 110 mm and foot_l.body.bb.height == 30 mm, "feet 110 x 30"
}
