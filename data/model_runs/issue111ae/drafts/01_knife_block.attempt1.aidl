# Request (kitchen): an upright knife block for 6 kitchen knives, cut from 6 mm birch ply.
# Two side panels 180 mm deep at the floor, 80 mm deep at the top, 240 mm tall, back edge
# vertical and front edge sloping, top corners rounded R4. Between them (150 mm clear between
# the sides) three shelves glued in by tabs into closed mortises in the sides:
# - a top plate 80 mm deep, its top face 10 mm below the top of the sides, with 6 knife slots
#   45 x 3 mm running front to back, 22 mm apart;
# - a blade guide 110 mm deep at 120 mm height (centre of its thickness) with 6 slots 45 x 4 mm
#   right under the top ones;
# - a base 160 mm deep, 13 mm up (centre of its thickness), where the tips rest.
# The left side carries "KNIFE BLOCK" engraved in bold filled letters 10 mm high, 60 mm up.

units mm
thickness 6 mm

import "std/joints.aidl"

param t = 6 mm, min = 3 mm, max = 9 mm
param clear = 150 mm, min = 130 mm, max = 200 mm   # inside width between the sides
param knives = 6, min = 3, max = 7
param pitch = 22 mm, min = 18 mm, max = 25 mm

# shelf heights (centre of the shelf's thickness, from the floor) and depths
top_y = 240 - 10 - t / 2
guide_y = 120
base_y = 13
top_d = 80
guide_d = 110
base_d = 160

# one side panel: the profile with three rows of closed mortises
def side() -> solid {
    body = Polygon([(0, 0), (180, 0), (80, 240), (0, 240)])
    Fillet(body.points[2], 4)
    Fillet(body.points[3], 4)
    m_top = tab_and_slot(part="slot", length=top_d, thickness=t, tabs=2, tab=20, screw=0,
                         cx=top_d / 2, cy=top_y)
    m_guide = tab_and_slot(part="slot", length=guide_d, thickness=t, tabs=2, tab=25, screw=0,
                           cx=guide_d / 2, cy=guide_y)
    m_base = tab_and_slot(part="slot", length=base_d, thickness=t, tabs=3, tab=25, screw=0,
                          cx=base_d / 2, cy=base_y)
}

# a shelf: clear + 2 t across (tabs reach through the sides), `depth` front to back,
# tabs on its left and right edges; knife slots (if any) centred `slot_off` from its middle
def shelf(depth=80 mm, tabs=2, tab=20 mm, slot_w=0 mm, slot_off=0 mm) -> solid {
    board = Rectangle(center=(0, 0), width=clear + 2 * t, height=depth)
    left_tabs = tab_and_slot(part="tab", length=depth, thickness=t, tabs=tabs, tab=tab,
                             screw=0, rotation=90, cx=-(clear / 2 + t), cy=0)
    right_tabs = tab_and_slot(part="tab", length=depth, thickness=t, tabs=tabs, tab=tab,
                              screw=0, rotation=-90, cx=clear / 2 + t, cy=0)
    if slot_w > 0 {
        hole knife {
            for i in range(knives) {
                s = Slot(center=((i - (knives - 1) / 2) * pitch, slot_off), length=45,
                         width=slot_w, rotation=90)
            }
        }
    }
}

assembly knife_block {
    left = side()
    right = side()
    # knife slots at 45 mm from the back edge of the sides in both plates
    top = shelf(depth=top_d, tabs=2, tab=20 mm, slot_w=3 mm, slot_off=45 - top_d / 2)
    guide = shelf(depth=guide_d, tabs=2, tab=25 mm, slot_w=4 mm, slot_off=45 - guide_d / 2)
    base = shelf(depth=base_d, tabs=3, tab=25 mm)

    left.bb.bottom_left == (0, 0)
    RightOf(right, left, gap=10)
    AlignBottom(right, left)
    RightOf(top, right, gap=10)
    AlignTop(top, right)
    Below(guide, top, gap=10)
    AlignLeft(guide, top)
    Below(base, guide, gap=10)
    AlignLeft(base, top)

    drawing label {
        word = Text("KNIFE BLOCK", position=(90, 60), size=10, font="sans:Bold",
                    valign="middle", fill=true)
    }
    CutInto(label, left)
    AlignCenterX(label, left.body)
    label.word.position.y == left.bb.bottom + 60

    # the request's numbers
    assert left.body.bb.height == 240 mm, "sides 240 mm tall"
    assert left.body.bb.width == 180 mm, "sides 180 mm deep at the floor"
    assert len(top.knife.s) == 6 and len(guide.knife.s) == 6, "6 knife slots in each plate"
    assert top.board.bb.width == 150 mm + 2 * t, "150 mm clear between the sides"
    assert top.knife.s[1].center.x - top.knife.s[0].center.x == 22 mm, "slots 22 mm apart"
    assert top_y + t / 2 == 230 mm, "top plate's top face 10 mm below the top"
    assert top.board.bb.height == 80 mm and guide.board.bb.height == 110 mm and
        base.board.bb.height == 160 mm, "shelf depths 80 / 110 / 160"
    assert label.word.bb.width < 170 mm, "the label fits on the side at 60 mm height"
}
