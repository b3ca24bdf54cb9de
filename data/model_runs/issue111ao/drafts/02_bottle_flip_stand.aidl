# Request (bathroom): a "last drop" stand that holds a shampoo bottle upside
# down, cut from 3 mm acrylic. A top plate 90 x 70 mm with R6 corners and a
# 34 mm hole in its centre that the bottle's cap drops through; "SHAMPOO"
# engraved (5 mm letters) centred between the hole and the front edge. Two
# identical legs 70 mm wide and 63 mm tall (including two 10 mm glue tabs,
# 3 mm long, on the top edge) with a foot arch 40 mm wide and 20 mm high (R8
# top corners) cut from the bottom edge. The legs stand under the plate's
# left and right edges, their middles 38 mm either side of the centre, glued
# into closed slots in the top plate. Three parts, laid out in a row to cut.

import "std/joints.aidl"

thickness 3 mm

plate_w = 90 mm
plate_d = 70 mm
neck_d = 34 mm
leg_w = 70 mm
leg_h = 63 mm
leg_offset = 38 mm

def leg() -> solid {
    body = Rectangle(center=(0, 0), width=70 mm, height=63 mm)
    tabs = tab_and_slot(part="tab", length=70 mm, thickness=3 mm, tabs=2, tab=10 mm,
                        screw=0, cx=0 mm, cy=31.5 mm)
    hole arch {
        a = RoundedRectangle(center=(0, -31.5 mm + 10 mm - 0.5 mm), width=40 mm, height=21 mm,
                             corner_radii=[8 mm, 8 mm, 0, 0], overrun=true)
    }
}

assembly bottle_stand {
    solid top {
        body = RoundedRectangle(center=(0, 0), width=plate_w, height=plate_d, corner_radius=6 mm)
        hole neck {
            c = Circle(center=(0, 0), diameter=neck_d)
        }
        left_slots = tab_and_slot(part="slot", length=70 mm, thickness=3 mm, tabs=2, tab=10 mm,
                                  screw=0, rotation=90 deg, cx=-leg_offset, cy=0 mm)
        right_slots = tab_and_slot(part="slot", length=70 mm, thickness=3 mm, tabs=2, tab=10 mm,
                                   screw=0, rotation=90 deg, cx=leg_offset, cy=0 mm)
        drawing label {
            word = Text("SHAMPOO", position=(0, -26), size=5, valign="middle")
        }
        AlignCenterX(label, body)
        label.bb.center_y == (body.bb.bottom + neck.c.bottom.y) / 2
    }

    left_leg = leg()
    right_leg = leg()

    RightOf(left_leg, top, gap=6 mm)
    RightOf(right_leg, left_leg, gap=6 mm)
    AlignBottom(left_leg, top)
    AlignBottom(right_leg, top)

    assert top.body.bb.width == 90 mm and top.body.bb.height == 70 mm, "top plate 90 x 70"
    assert top.neck.c.diameter == 34 mm, "34 mm hole for the cap"
    assert left_leg.body.bb.width == 70 mm and left_leg.body.bb.height == 63 mm, "legs 70 x 63"
    assert right_leg.body.bb.height == 63 mm, "legs 63 tall"
    assert left_leg.arch.a.bb.top - left_leg.body.bb.bottom == 20 mm, "foot arch 20 high"
    assert left_leg.arch.a.bb.width == 40 mm, "foot arch 40 wide"
    assert top.right_slots.cx - top.left_slots.cx == 2 * 38 mm, "legs 38 mm either side"
}
