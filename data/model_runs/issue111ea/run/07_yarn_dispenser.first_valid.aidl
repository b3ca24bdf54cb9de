# Request (crafts): a yarn dispenser for three-colour knitting, 3 mm ply. A finger-jointed
# box 300 x 120 x 130 outside (fingers at least 15 mm) with a lift-off lid (lip clearance
# 0.3 mm). Three compartments for 90 mm balls of yarn: two dividers 100 mm high standing on
# the floor at 49 mm either side of the centre, each held by one 40 mm tenon at each end
# through a mortise in the front and back walls (0.1 mm clearance). A 12 mm eyelet in the
# lid over the middle of each compartment (100 mm apart), with a 16 mm hole under it in the
# lip, and the letters A, B, C (8 mm, bold sans, engraved filled) 22 mm in front of the
# eyelets. "NANA'S YARN" engraved filled on the front wall (bold serif, 18 mm capitals),
# centred, its middle 100 mm above the bottom edge.

import "std/boxes.aidl"
import "std/joints.aidl"

thickness 3 mm

ply = 3 mm
box_l = 300 mm
box_d = 120 mm
box_h = 130 mm
div_h = 100 mm
div_x = 49 mm
tenon = 40 mm
fit = 0.1 mm
pitch = 100 mm

def divider() -> solid {
    # x: across the box, the tenons' tips flush with the walls' outer faces
    body = Rectangle(center=(0, div_h / 2), width=box_d, height=div_h)
    left_t = tab_and_slot(part="tab", length=div_h, thickness=ply, tabs=1, tab=tenon,
                          screw=0, rotation=90 deg, cx=-box_d / 2, cy=div_h / 2)
    right_t = tab_and_slot(part="tab", length=div_h, thickness=ply, tabs=1, tab=tenon,
                           screw=0, rotation=-90 deg, cx=box_d / 2, cy=div_h / 2)
}

def mortises() -> hole {
    a = Rectangle(center=(-div_x, 0), width=ply + fit, height=tenon + fit)
    b = Rectangle(center=(div_x, 0), width=ply + fit, height=tenon + fit)
}

assembly yarn_dispenser {
    box = lid_box(length=box_l, width=box_d, height=box_h, thickness=ply, finger=15 mm,
                  clearance=0.3 mm)

    # the tenons' middle stands ply + div_h / 2 above the box's bottom edge
    front_m = mortises()
    back_m = mortises()
    AlignCenterX(front_m, box.body.front)
    front_m.bb.center_y == box.body.front.bb.bottom + ply + div_h / 2
    AlignCenterX(back_m, box.body.back)
    back_m.bb.center_y == box.body.back.bb.bottom + ply + div_h / 2
    CutInto(front_m, box.body.front)
    CutInto(back_m, box.body.back)

    drawing name {
        t = Text("NANA'S YARN", position=(0, 0), size=18, font="serif:Bold",
                 valign="middle", fill=true)
    }
    AlignCenterX(name, box.body.front)
    name.t.position.y == box.body.front.bb.bottom + 100 mm
    CutInto(name, box.body.front)

    hole eyes {
        for i in range(3) {
            e = Circle(center=((i - 1) * pitch, 0), diameter=12)
        }
    }
    CenterInside(eyes, box.lid)
    CutInto(eyes, box.lid)

    drawing letters {
        for i in range(3) {
            l = Text(["A", "B", "C"][i], position=((i - 1) * pitch, -22), size=8,
                     font="sans:Bold", valign="middle", fill=true)
        }
    }
    AlignCenterX(letters, box.lid)
    letters.l[0].position.y == eyes.e[0].center.y - 22 mm
    CutInto(letters, box.lid)

    hole lip_eyes {
        for i in range(3) {
            e = Circle(center=((i - 1) * pitch, 0), diameter=16)
        }
    }
    CenterInside(lip_eyes, box.lip)
    CutInto(lip_eyes, box.lip)

    div_l = divider()
    div_r = divider()
    RightOf(div_l, box, gap=10)
    AlignTop(div_l, box)
    Below(div_r, div_l, gap=10)
    AlignLeft(div_r, div_l)

    # 3D: the box stands on z = 0 centred; dividers across it on the floor
    Place(div_l, position=(-div_x - ply / 2, 0, ply), face="right", up="up")
    Place(div_r, position=(div_x - ply / 2, 0, ply), face="right", up="up")

    assert len(eyes.e) == 3, "three eyelets"
    assert eyes.e[0].diameter == 12 mm and lip_eyes.e[0].diameter == 16 mm, "eyelet sizes"
    assert eyes.e[1].center.x - eyes.e[0].center.x == 100 mm, "eyelets 100 apart"
    assert div_l.body.bb.height == 100 mm, "dividers 100 high"
    assert front_m.b.center.x - front_m.a.center.x == 2 * 49 mm, "dividers 49 either side"
    assert front_m.a.height == 40 mm + 0.1 mm, "mortise 0.1 clearance"
    assert div_l.left_t.gap[0].bb.width == 3 mm, "tenons as long as the wall is thick"
    assert name.t.size == 18 mm, "18 mm name"
    assert distance(name, front_m) >= 5 mm, "name clear of the mortises"
    assert name.bb.width <= box.body.front.bb.width - 30 mm, "name fits the front"
    assert letters.l[0].size == 8 mm, "8 mm letters"
    assert eyes.e[0].center.y - letters.l[0].position.y == 22 mm, "letters 22 in front"
    assert distance(letters, eyes) >= 2 mm, "letters clear of the eyelets"
}
