# Request (pets): a dog-proof cat feeding station, 6 mm ply.
# A finger-jointed box 450 long x 350 deep x 300 high (outside), 30 mm fingers, with a
# lift-off lid. In the front a round cat door 150 mm across, centred left to right, its
# centre 130 mm above the box's bottom edge. "CATS ONLY" engraved filled (30 mm capitals,
# sans bold), centred, its middle 45 mm below the front's top edge; a filled paw print
# (a 28 x 22 mm pad and four 10 mm toes) 110 mm either side of the door's centre.
# In the lid a 100 x 25 mm hand slot in the middle; in the back five 20 mm vent holes
# in a row, 40 mm apart, 60 mm below the top edge.
# Inside: a bowl holder, a 400 x 180 plate with two 125 mm bowl holes 190 mm apart,
# "FOOD" and "WATER" (8 mm) in front of them, on two legs 180 x 40 mm, each glued into
# the plate with one 40 mm tenon through a mortise 170 mm from the plate's middle.

units mm
thickness 6 mm

import "std/joints.aidl"

t = 6 mm
L = 450 mm
D = 350 mm
H = 300 mm
door_d = 150 mm
door_up = 130 mm
plate_w = 400 mm
plate_d = 180 mm
bowl_d = 125 mm
bowl_pitch = 190 mm
leg_h = 40 mm
leg_x = 170 mm

def paw() -> drawing {
    pad = Ellipse(center=(0, 0), rx=14, ry=11, fill=true)
    toe1 = Circle(center=(-17, 12), radius=5, fill=true)
    toe2 = Circle(center=(-6, 20), radius=5, fill=true)
    toe3 = Circle(center=(6, 20), radius=5, fill=true)
    toe4 = Circle(center=(17, 12), radius=5, fill=true)
}

def leg() -> solid {
    body = Rectangle(bottom_left=(-plate_d / 2, 0), width=plate_d, height=leg_h + t)
    tenon = tab_and_slot(part="tab", length=plate_d, thickness=t, tabs=1, tab=40 mm, screw=0,
                         cx=0, cy=leg_h + t)
}

assembly station {
    box = finger_box(length=L, depth=D, height=H, thickness=t, finger=30 mm, closed=true, gap=10 mm)

    hole door { c = Circle(center=(0, 0), diameter=door_d) }
    AlignCenterX(door, box.front)
    door.c.center.y == box.front.bb.bottom + door_up
    CutInto(door, box.front)

    drawing sign {
        words = Text("CATS ONLY", position=(0, 0), size=30, font="sans:Bold", valign="middle", fill=true)
    }
    AlignCenterX(sign, box.front)
    sign.words.position.y == box.front.bb.top - 45 mm
    CutInto(sign, box.front)

    paw_l = paw()
    paw_r = paw()
    At(paw_l.pad.center, door.c.center, dx=-110, dy=0)
    At(paw_r.pad.center, door.c.center, dx=110, dy=0)
    CutInto(paw_l, box.front)
    CutInto(paw_r, box.front)

    hole hand { s = Slot(center=(0, 0), length=100, width=25) }
    CenterInside(hand, box.lid)
    CutInto(hand, box.lid)

    hole vents {
        for i in range(5) {
            v = Circle(center=((i - 2) * 40, 0), diameter=20)
        }
    }
    AlignCenterX(vents, box.back)
    vents.v[0].center.y == box.back.bb.top - 60 mm
    CutInto(vents, box.back)

    solid holder {
        body = Rectangle(center=(0, 0), width=plate_w, height=plate_d)
        hole bowls {
            b0 = Circle(center=(-bowl_pitch / 2, 0), diameter=bowl_d)
            b1 = Circle(center=(bowl_pitch / 2, 0), diameter=bowl_d)
        }
        left_mortise = tab_and_slot(part="slot", length=plate_d, thickness=t, tabs=1, tab=40 mm, screw=0,
                                    rotation=90 deg, cx=-leg_x, cy=0)
        right_mortise = tab_and_slot(part="slot", length=plate_d, thickness=t, tabs=1, tab=40 mm, screw=0,
                                     rotation=90 deg, cx=leg_x, cy=0)
        drawing words {
            food = Text("FOOD", position=(-bowl_pitch / 2, -plate_d / 2 + 13), size=8, valign="middle")
            water = Text("WATER", position=(bowl_pitch / 2, -plate_d / 2 + 13), size=8, valign="middle")
        }
    }
    left_leg = leg()
    right_leg = leg()

    # 3D: the box stands on z = 0 centred on x = y = 0 (the template places it);
    # the holder's legs stand on the floor (z = t), the plate on them
    Place(holder, position=(0, 0, t + leg_h))
    Place(left_leg, position=(-leg_x + t / 2, 0, t), face="left", up="up")
    Place(right_leg, position=(leg_x + t / 2, 0, t), face="left", up="up")

    # on the sheet: beside the box's net
    RightOf(holder, box, gap=20)
    AlignTop(holder, box)
    Below(left_leg, holder, gap=10)
    AlignLeft(left_leg, holder)
    RightOf(right_leg, left_leg, gap=10)
    AlignTop(right_leg, left_leg)

    assert box.front.bb.width == 450 mm and box.front.bb.height == 300 mm, "front 450 x 300"
    assert door.c.diameter == 150 mm, "door 150 across"
    assert abs(door.c.center.y - box.front.bb.bottom - 130 mm) < 0.01 mm, "door centre 130 up"
    assert abs(door.c.center.y - door.c.radius - box.front.bb.bottom - 55 mm) < 0.01 mm, "sill 55 mm"
    assert abs(box.front.bb.top - sign.words.position.y - 45 mm) < 0.01 mm, "sign 45 below the top"
    assert abs(paw_r.pad.center.x - door.c.center.x - 110 mm) < 0.01 mm, "paws 110 from the door"
    assert len(vents.v) == 5, "five vents"
    assert holder.body.bb.width == 400 mm and holder.body.bb.height == 180 mm, "holder 400 x 180"
    assert abs(holder.bowls.b1.center.x - holder.bowls.b0.center.x - 190 mm) < 0.01 mm, "bowls 190 apart"
    assert holder.bowls.b0.diameter == 125 mm, "125 mm bowl holes"
    assert plate_w < L - 2 * t and plate_d < D - 2 * t, "the holder fits inside"
}
