# Kitchen: a bread slicing guide of 4 mm plywood. A base 220 x 160 mm (R5 corners) holds two
# upright walls 220 mm long and 130 mm tall (tabs included) that stand 140 mm apart inside
# (wall middles 72 mm either side of the base's centre line) in glued mortises: 3 tabs
# 20 mm wide per wall. Each wall has 9 knife slots 2.5 mm wide and 100 mm deep from its top
# edge, 15 mm apart (slices of 15 mm), centred along the wall; the walls' top corners R8.
import "std/joints.aidl"

thickness 4 mm
kerf 0.15 mm

param slice = 15 mm, min = 10 mm, max = 24 mm
slots = 9
wall_len = 220 mm
wall_h = 130 mm
slot_depth = 100 mm

def wall() -> solid {
    body = RoundedRectangle(center=(0, 0), width=wall_len, height=wall_h,
                            corner_radii=[8, 8, 0, 0])
    hole knife {
        for i in range(slots) {
            s = Rectangle(center=((i - (slots - 1) / 2) * slice, wall_h / 2 - slot_depth / 2),
                          width=2.5, height=slot_depth)
            o = Rectangle(center=((i - (slots - 1) / 2) * slice, wall_h / 2 + 1),
                          width=2.5, height=2, overrun=true)
        }
    }
    # 3 glued tabs on the bottom edge; the shoulder line is one thickness above the tips
    joint = tab_and_slot(part="tab", length=wall_len, thickness=4 mm, tabs=3, tab=20 mm,
                         screw=0, cx=0 mm, cy=-wall_h / 2 + 4 mm)
}

assembly bread_guide {
    solid base {
        plate = RoundedRectangle(center=(0, 0), width=220, height=160, corner_radius=5)
        near = tab_and_slot(part="slot", length=wall_len, thickness=4 mm, tabs=3, tab=20 mm,
                            screw=0, cx=0 mm, cy=-72 mm)
        far = tab_and_slot(part="slot", length=wall_len, thickness=4 mm, tabs=3, tab=20 mm,
                           screw=0, cx=0 mm, cy=72 mm)
    }
    wall_a = wall()
    wall_b = wall()
    Above(wall_a, base, gap=10)
    Above(wall_b, wall_a, gap=10)
    AlignCenterX(wall_a, base)
    AlignCenterX(wall_b, base)

    assert base.plate.bb.width == 220 mm, "base 220 long"
    assert base.plate.bb.height == 160 mm, "base 160 deep"
    assert wall_a.body.bb.width == 220 mm, "wall 220 long"
    assert wall_a.body.bb.height == 130 mm, "wall 130 tall with tabs"
    assert len(wall_a.knife.s) == 9, "9 knife slots"
    assert wall_a.knife.s[1].center.x - wall_a.knife.s[0].center.x == 15 mm, "15 mm slices"
    assert wall_a.knife.s[0].bb.height == 100 mm, "slots 100 deep"
    assert wall_a.body.bb.top - wall_a.knife.s[0].bb.bottom == 100 mm, "slot depth from the top edge"
    assert base.far.slot[0].center.y - base.near.slot[0].center.y == 144 mm, "walls 140 apart inside"
}
