# Request: a small bathroom medicine cabinet to hang on the wall, from 6 mm ply: outside
# 300 mm wide, 400 mm tall, 120 mm deep, finger-jointed (15 mm fingers), the door hinged on
# the left on pins cut from the sheet, so no metal hinges to rust. Inside, an adjustable
# shelf on 5 mm shelf pins: in each side wall two rows (25 mm and 85 mm from the wall) of
# five holes at 30 mm pitch around mid-height. The shelf is 1 mm narrower than the inside
# and 2 mm shallower. A 5 mm hole for a knob 20 mm from the door's free edge at mid-height,
# a filled cross 60 mm across (arms 18 wide) and "MEDICINE" 14 mm high engraved on the
# door. Two keyholes in the back, 40 mm below the top and 200 mm apart, to hang it on two
# screws.

units mm
t = 6 mm
thickness t
import "std/boxes.aidl"
import "std/plates.aidl"

cab_w = 300 mm    # across the wall
cab_h = 400 mm    # up the wall
cab_d = 120 mm    # out from the wall
shelf_d = cab_d - 2 * t - 2 mm

def pin_rows() -> hole {
    for i in range(5) {
        near = Circle(center=((i - 2) * 30 mm, 0), diameter=5 mm)
        far = Circle(center=((i - 2) * 30 mm, 60 mm), diameter=5 mm)
    }
}

assembly cabinet {
    # the box lies on its back in its own frame: its length runs up the wall, its width
    # across, its height out from the wall; the lid is the door, its hinge edge (+y) on the left
    b = hinged_box(length=cab_h, width=cab_w, height=cab_d, thickness=t, finger=15 mm)

    right_pins = pin_rows()
    left_pins = pin_rows()
    AlignCenterX(right_pins, b.front)
    right_pins.near[0].center.y == b.front.bb.bottom + 25 mm
    AlignCenterX(left_pins, b.back)
    left_pins.near[0].center.y == b.back.bb.bottom + 25 mm
    CutInto(right_pins, b.front)
    CutInto(left_pins, b.back)

    hole knob {
        c = Circle(center=(0, 0), diameter=5 mm)
    }
    AlignCenterX(knob, b.lid)
    knob.c.center.y == b.lid.bb.bottom + 20 mm
    CutInto(knob, b.lid)

    drawing door_mark {
        cross = Polygon([(-9, 30), (9, 30), (9, 9), (30, 9), (30, -9), (9, -9), (9, -30),
                         (-9, -30), (-9, -9), (-30, -9), (-30, 9), (-9, 9)], fill=true)
        word = Text("MEDICINE", position=(-55 mm, 0), size=14 mm, rotation=-90 deg,
                    font="sans:Bold", valign="middle", fill=true)
    }
    AlignCenterY(door_mark.cross, b.lid)
    door_mark.cross.center.x == b.lid.bb.center_x + 30 mm
    CutInto(door_mark, b.lid)

    hang_a = keyhole(head=8 mm, slot_width=4 mm, length=10 mm, direction=0 deg)
    hang_b = keyhole(head=8 mm, slot_width=4 mm, length=10 mm, direction=0 deg)
    hang_a.head_hole.center.x == b.bottom.bb.right - 40 mm
    hang_b.head_hole.center.x == b.bottom.bb.right - 40 mm
    hang_a.head_hole.center.y == b.bottom.bb.center_y + 100 mm
    hang_b.head_hole.center.y == b.bottom.bb.center_y - 100 mm
    CutInto(hang_a, b.bottom)
    CutInto(hang_b, b.bottom)

    solid shelf {
        r = Rectangle(center=(0, 0), width=cab_w - 2 * t - 1 mm, height=shelf_d)
    }
    RightOf(shelf, b, gap=10 mm)
    AlignBottom(shelf, b)

    # standing on the wall: box x up, box y to the left, box z out of the wall (to -y)
    Place(b, rotation=(90 deg, -90 deg, 0), position=(0, cab_d, cab_h / 2))
    # on the middle pins (their tops 2.5 mm above mid-height), against the back
    Place(shelf, position=(0, cab_d - t - shelf_d / 2, cab_h / 2 + 2.5 mm))

    assert len(right_pins.near) == 5 and len(left_pins.far) == 5, "five holes per row"
    assert right_pins.near[1].center.x - right_pins.near[0].center.x == 30 mm, "30 mm pitch"
    assert right_pins.far[0].center.y - b.front.bb.bottom == 85 mm, "far row 85 mm out"
    assert left_pins.far[0].center.y - b.back.bb.bottom == 85 mm, "far row 85 mm out (left)"
    assert b.lid.bb.bottom + 20 mm == knob.c.center.y, "knob 20 mm from the free edge"
    assert b.bottom.bb.right - hang_a.head_hole.center.x == 40 mm, "keyholes 40 mm below the top"
    assert hang_a.head_hole.center.y - hang_b.head_hole.center.y == 200 mm, "keyholes 200 apart"
    assert shelf.r.width == 300 mm - 2 * t - 1 mm, "shelf 1 mm narrower than inside"
    assert door_mark.cross.bb.width == 60 mm, "cross 60 mm across"
    assert distance(door_mark, knob) >= 5 mm, "engraving clear of the knob hole"
}
