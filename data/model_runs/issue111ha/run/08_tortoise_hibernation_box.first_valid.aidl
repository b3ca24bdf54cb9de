# Request (pets): "A hibernation box for Sheldon, our Hermann's tortoise, to sit in the cool
# garage over winter. A finger-jointed box of 6 mm ply, 400 x 300 x 250 mm outside with a
# lift-off lid (30 mm fingers). Air: 18 holes of 12 mm in the lid, 3 rows x 6, 40 mm apart,
# through the lid's lip as well, and a row of six 12 mm holes 50 mm apart, 30 mm below the top
# of the front and back walls. A 90 x 25 mm hand-hold slot, upright, 40 mm in from the top
# edge of each end wall. On the lid, engraved: SHELDON in 30 mm bold, HIBERNATING - DO NOT
# DISTURB in 12 mm bold, and IN ____ OUT ____ in 8 mm letters to pencil the dates on."

import "std/boxes.aidl"

thickness 6 mm

param length = 400 mm, min = 300 mm, max = 500 mm
param width = 300 mm, min = 220 mm, max = 400 mm
param height = 250 mm, min = 180 mm, max = 320 mm
param vent_d = 12 mm, min = 8 mm, max = 16 mm

def lid_vents() -> hole {
    for r in range(3) {
        for c in range(6) {
            v = Circle(center=((c - 2.5) * 40 mm, (r - 1) * 40 mm), diameter=vent_d)
        }
    }
}

def wall_vents() -> hole {
    for i in range(6) {
        v = Circle(center=((i - 2.5) * 50 mm, 0), diameter=vent_d)
    }
}

def hand_hold() -> hole {
    s = Slot(center=(0, 0), length=90 mm, width=25 mm, rotation=90 deg)
}

assembly hibernation_box {
    box = lid_box(length=length, width=width, height=height, thickness=6 mm, finger=30 mm)

    top_vents = lid_vents()
    CenterInside(top_vents, box.lid)
    CutInto(top_vents, box.lid)
    lip_vents = lid_vents()
    CenterInside(lip_vents, box.lip)
    CutInto(lip_vents, box.lip)

    front_vents = wall_vents()
    AlignCenterX(front_vents, box.body.front)
    front_vents.v[0].center.y == box.body.front.bb.top - 30 mm
    CutInto(front_vents, box.body.front)
    back_vents = wall_vents()
    AlignCenterX(back_vents, box.body.back)
    back_vents.v[0].center.y == box.body.back.bb.top - 30 mm
    CutInto(back_vents, box.body.back)

    left_grip = hand_hold()
    AlignCenterY(left_grip, box.body.left)
    left_grip.s.center.x == box.body.left.bb.left + 40 mm
    CutInto(left_grip, box.body.left)
    right_grip = hand_hold()
    AlignCenterY(right_grip, box.body.right)
    right_grip.s.center.x == box.body.right.bb.right - 40 mm
    CutInto(right_grip, box.body.right)

    drawing lid_text {
        name = Text("SHELDON", position=(0, 95 mm), size=30, font="sans:Bold", fill=true,
                    valign="middle")
        warning = Text("HIBERNATING - DO NOT DISTURB", position=(0, -78 mm), size=12,
                       font="sans:Bold", fill=true, valign="middle")
        dates = Text("IN ________    OUT ________", position=(0, -110 mm), size=8,
                     valign="middle")
    }
    At(lid_text.name.position, box.lid.bb.center, dy=95 mm)
    CutInto(lid_text, box.lid)

    assert box.length == 400 mm and box.width == 300 mm and box.height == 250 mm, "400 x 300 x 250 outside"
    assert len(top_vents.v) == 3 and len(top_vents.v[0]) == 6, "3 x 6 lid vents"
    assert top_vents.v[0][1].center.x - top_vents.v[0][0].center.x == 40 mm, "40 mm apart"
    assert len(front_vents.v) == 6 and len(back_vents.v) == 6, "six vents front and back"
    assert box.body.front.bb.top - front_vents.v[0].center.y == 30 mm, "30 mm below the top"
    assert left_grip.s.length == 90 mm and left_grip.s.width == 25 mm, "90 x 25 hand holds"
    assert distance(lid_text, top_vents) >= 8 mm, "text clear of the vents"
    assert lid_text.bb.width <= box.lid.bb.width - 30 mm, "text on the lid"
    assert lid_text.bb.top <= box.lid.bb.top - 10 mm and lid_text.bb.bottom >= box.lid.bb.bottom + 10 mm, "text within the lid"
}
