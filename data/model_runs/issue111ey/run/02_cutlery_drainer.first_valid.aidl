# Request (kitchen): a cutlery drainer caddy for the draining board, in 3 mm clear acrylic.
# An open-top finger-jointed box 180 mm long, 90 mm deep, 140 mm tall (outside), 10 mm
# fingers, split into three equal compartments (knives, forks, spoons) by two dividers
# 110 mm tall. Each divider stands on the bottom and has two 25 mm tabs at each end through
# mortises in the front and back, and two 20 mm tabs under it through the bottom (glued with
# acrylic cement, 0.1 mm clearance in the mortises). The bottom of each compartment has a
# grid of 6 mm drain holes, 3 across and 5 deep on a 14 mm pitch. "KNIVES", "FORKS" and
# "SPOONS" are engraved (filled, bold, 8 mm) on the front, centred over their compartments,
# their tops 12 mm below the rim.

units mm
t = 3 mm
thickness t

length = 180 mm
depth = 90 mm
height = 140 mm
div_h = 110 mm
fit = 0.1 mm
inner = length - 2 * t
cell = (inner - 2 * t) / 3            # compartment width, 56 mm
div_x = cell / 2 + t / 2               # dividers' mid-planes at +-div_x
pitch = 14 mm
names = ["KNIVES", "FORKS", "SPOONS"]

import "std/joints.aidl"

def divider() -> solid {
    body = Rectangle(bottom_left=(-depth / 2, 0), width=depth, height=div_h)
    right_end = tab_and_slot(part="tab", length=div_h, thickness=t, tabs=2, tab=25 mm,
                             screw=0, rotation=-90 deg, cx=depth / 2, cy=div_h / 2)
    left_end = tab_and_slot(part="tab", length=div_h, thickness=t, tabs=2, tab=25 mm,
                            screw=0, rotation=90 deg, cx=-depth / 2, cy=div_h / 2)
    foot = tab_and_slot(part="tab", length=depth, thickness=t, tabs=2, tab=20 mm,
                        screw=0, rotation=180 deg, cx=0, cy=0)
}

# the mortises for one divider's end, in a wall's frame (wall bottom edge at y = 0)
def end_mortises() -> hole {
    span = Rectangle(bottom_left=(-div_x - 1, 0), width=2 * div_x + 2, height=div_h,
                     construction=true)
    a = tab_and_slot(part="slot", length=div_h, thickness=t, tabs=2, tab=25 mm, screw=0,
                     clearance=fit, rotation=90 deg, cx=div_x, cy=div_h / 2)
    b = tab_and_slot(part="slot", length=div_h, thickness=t, tabs=2, tab=25 mm, screw=0,
                     clearance=fit, rotation=90 deg, cx=-div_x, cy=div_h / 2)
}

assembly drainer {
    box = finger_box(length=length, depth=depth, height=height, thickness=t, finger=10 mm,
                     closed=false)
    div_l = divider()
    div_r = divider()

    front_m = end_mortises()
    back_m = end_mortises()
    AlignCenterX(front_m.span, box.front)
    AlignBottom(front_m.span, box.front)
    CutInto(front_m, box.front)
    AlignCenterX(back_m.span, box.back)
    AlignBottom(back_m.span, box.back)
    CutInto(back_m, box.back)

    hole floor {
        fa = tab_and_slot(part="slot", length=depth, thickness=t, tabs=2, tab=20 mm,
                          screw=0, clearance=fit, rotation=90 deg, cx=div_x, cy=0)
        fb = tab_and_slot(part="slot", length=depth, thickness=t, tabs=2, tab=20 mm,
                          screw=0, clearance=fit, rotation=90 deg, cx=-div_x, cy=0)
        for c in range(3) {
            for i in range(3) {
                for k in range(5) {
                    d = Circle(center=((c - 1) * (cell + t) + (i - 1) * pitch,
                                       (k - 2) * pitch), diameter=6)
                }
            }
        }
    }
    CenterInside(floor, box.bottom)
    CutInto(floor, box.bottom)

    drawing labels {
        for c in range(3) {
            w = Text(names[c], position=((c - 1) * (cell + t), 0), size=8, font="sans:Bold",
                     valign="top", fill=true, max_width=cell - 6)
        }
    }
    AlignCenterX(labels, box.front)
    labels.w[0].position.y == box.front.bb.top - 12 mm
    CutInto(labels, box.front)

    # flat: the dividers beside the box's net
    RightOf(div_l, box, gap=10)
    AlignTop(div_l, box)
    Below(div_r, div_l, gap=10)
    AlignLeft(div_r, div_l)

    # assembled: the box stands on z = 0 centred on x = y = 0; dividers across the depth
    Place(div_l, position=(-div_x - t / 2, 0, 0), face="right", up="up")
    Place(div_r, position=(div_x - t / 2, 0, 0), face="right", up="up")

    assert box.bottom.outline.width == 180 mm and box.bottom.outline.height == 90 mm,
        "180 long, 90 deep"
    assert box.front.outline.height == 140 mm, "140 tall"
    assert div_l.body.height == 110 mm, "dividers 110 tall"
    assert len(floor.d) == 3 and len(floor.d[0]) == 3 and len(floor.d[0][0]) == 5,
        "3 x 5 drain holes in each of 3 compartments"
    assert abs(3 * cell + 2 * t - (180 mm - 2 * 3 mm)) < 0.001 mm, "three equal compartments"
}
