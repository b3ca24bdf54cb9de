# Request (parties): a pirate-party treasure chest for the favours, 3 mm ply. An open
# finger-jointed box 200 x 120 x 90 outside (fingers at least 12 mm) with a hand slot
# 40 x 12 in each end, its middle 20 mm below the top. A lift-off barrel lid: two end
# pieces 114 wide (a 10 mm straight skirt under a semicircle of radius 57) set 3 mm in,
# flush with the lid's ends, and one living-hinge sheet 200 long wrapped over them: 10 mm
# flat skirt front and back and a 180 degree bend round the ends' semicircle (hinge pitch
# 2.5, cuts 20, bridges 3). The box front engraved filled: two iron straps 14 wide and 84
# high at 60 mm either side of the centre, a lock plate outline 30 x 36 (R4) at the top
# middle with a filled keyhole in it, and "PETE'S LOOT" (bold serif, 14 mm, no wider than
# 90 mm) 20 mm below the front's centre.

import "std/joints.aidl"
import "std/plates.aidl"

thickness 3 mm

ply = 3 mm
box_l = 200 mm
box_d = 120 mm
box_h = 90 mm
skirt = 10 mm
lid_r = 57 mm
bend_w = pi * (lid_r + ply / 2)
sheet_w = 2 * skirt + bend_w

def lid_end() -> solid {
    # y = 0: the skirt's foot (the box's top edge)
    foot = Rectangle(bottom_left=(-lid_r, 0), width=2 * lid_r, height=skirt)
    dome = Sector(center=(0, skirt), radius=lid_r, start_angle=0 deg, end_angle=180 deg)
}

assembly treasure_chest {
    box = finger_box(length=box_l, depth=box_d, height=box_h, thickness=ply, finger=12 mm,
                     closed=false)

    hole grip_l { s = Slot(center=(0, 0), length=40, width=12, rotation=90 deg) }
    hole grip_r { s = Slot(center=(0, 0), length=40, width=12, rotation=90 deg) }
    # the sides lie on their side, top edge outward (the left's at -x, the right's at +x)
    AlignCenterY(grip_l, box.left)
    grip_l.s.center.x == box.left.bb.left + 20 mm
    AlignCenterY(grip_r, box.right)
    grip_r.s.center.x == box.right.bb.right - 20 mm
    CutInto(grip_l, box.left)
    CutInto(grip_r, box.right)

    drawing front_art {
        strap_l = Rectangle(center=(-60, 0), width=14, height=84, fill=true)
        strap_r = Rectangle(center=(60, 0), width=14, height=84, fill=true)
        lock = RoundedRectangle(center=(0, 42 - 18), width=30, height=36, corner_radius=4)
        key_eye = Circle(center=(0, 28), radius=4, fill=true)
        key_tail = Trapezoid(center=(0, 20), bottom_width=7, top_width=3, height=12,
                             fill=true)
        word = Text("PETE'S LOOT", position=(0, -20), size=14, font="serif:Bold",
                    valign="middle", max_width=90, fill=true)
    }
    CenterInside(front_art, box.front)
    CutInto(front_art, box.front)

    end_l = lid_end()
    end_r = lid_end()

    solid sheet {
        body = Rectangle(center=(0, 0), width=sheet_w, height=box_l)
        hinge = living_hinge(width=bend_w, height=box_l, pitch=2.5 mm, cut=20 mm,
                             bridge=3 mm)
    }

    # flat: lid parts to the right of the box's net
    RightOf(sheet, box, gap=10)
    AlignTop(sheet, box)
    RightOf(end_l, sheet, gap=10)
    AlignTop(end_l, sheet)
    Below(end_r, end_l, gap=10)
    AlignLeft(end_r, end_l)

    # 3D: the box stands on z = 0 centred; the lid sits on its top edge
    Place(end_l, position=(-box_l / 2, 0, box_h), face="right", up="up")
    Place(end_r, position=(box_l / 2, 0, box_h), face="left", up="up")
    # the sheet: outer face at the front (y = -box_d / 2), inner face looking back, its
    # drawing's y along the chest, its x up the front skirt and then bent over the top
    Place(sheet, position=(0, -box_d / 2, box_h + sheet_w / 2), face="back", up="right")
    Bend(sheet, at=0, angle=180 deg, radius=lid_r)

    assert box_l == 200 mm and box_d == 120 mm and box_h == 90 mm, "box size"
    assert 2 * lid_r + 2 * ply == 120 mm, "lid ends fill the depth inside the sheet"
    assert end_l.bb.height == 10 mm + 57 mm, "end: skirt and semicircle"
    assert end_l.bb.width == 114 mm, "end 114 wide"
    assert sheet.body.bb.height == 200 mm, "sheet 200 long"
    assert sheet.hinge.width == bend_w, "hinge band covers the bend"
    assert grip_l.s.length == 40 mm and grip_l.s.width == 12 mm, "hand slot 40 x 12"
    assert front_art.word.bb.width <= 90 mm, "name no wider than 90"
    assert distance(front_art.word, front_art.strap_r) >= 3 mm, "name between the straps"
    assert distance(front_art.word, front_art.lock) >= 2 mm, "name under the lock plate"
    assert front_art.strap_r.center.x - front_art.strap_l.center.x == 120 mm,
        "straps 60 either side"
    assert front_art.bb.height <= box_h - 6 mm, "straps inside the front"
}
