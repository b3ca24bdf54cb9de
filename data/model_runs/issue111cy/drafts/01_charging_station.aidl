# Request (home): a family charging station for the hall table. A closed finger-jointed box
# of 6 mm birch ply, 260 mm long, 130 mm deep, 100 mm tall outside, 15 mm fingers; a power
# strip lives inside. The lid has 4 slots, 12 mm wide and 100 mm long, running front to
# back, on a 55 mm pitch and centred on the lid, for phones and a tablet to stand in (their
# cables come up through the same slots). The back has a 40 x 25 mm rounded cable exit,
# centred, its bottom 10 mm above the box's bottom edge, for the strip's plug. The front
# carries "CHARGE" in 30 mm bold letters, engraved filled, centred.

import "std/joints.aidl"

thickness 6 mm

param slots_n = 4, min = 1, max = 4
param pitch = 55 mm, min = 40 mm, max = 60 mm

assembly station {
    box = finger_box(length=260 mm, depth=130 mm, height=100 mm, thickness=6 mm,
                     finger=15 mm, closed=true, outside=true)

    hole device_slots {
        for i in range(slots_n) {
            s = Slot(center=(i * pitch, 0), length=100 mm, width=12 mm, rotation=90 deg)
        }
    }
    CenterInside(device_slots, box.lid)
    CutInto(device_slots, box.lid)

    hole cable_exit {
        s = Slot(center=(0, 0), length=40 mm, width=25 mm)
    }
    AlignCenterX(cable_exit, box.back)
    cable_exit.bb.bottom == box.back.bb.bottom + 10 mm
    CutInto(cable_exit, box.back)

    drawing label {
        t = Text("CHARGE", position=(0, 0), size=30 mm, font="sans:Bold", valign="middle",
                 fill=true)
    }
    CenterInside(label, box.front)
    CutInto(label, box.front)

    # the request's numbers
    assert box.lid.bb.width == 260 mm and box.lid.bb.height == 130 mm, "lid 260 x 130"
    assert box.front.bb.height == 100 mm, "100 mm tall"
    assert len(device_slots.s) == 4, "4 device slots"
    assert device_slots.s[1].center.x - device_slots.s[0].center.x == 55 mm, "55 mm pitch"
    assert device_slots.s[0].width == 12 mm and device_slots.s[0].length == 100 mm,
        "slots 12 x 100"
    assert abs(device_slots.bb.center_x - box.lid.bb.center_x) < 0.01 mm and
        abs(device_slots.bb.center_y - box.lid.bb.center_y) < 0.01 mm, "slots centred on the lid"
    assert cable_exit.bb.width == 40 mm and cable_exit.bb.height == 25 mm, "cable exit 40 x 25"
    assert cable_exit.bb.bottom - box.back.bb.bottom == 10 mm, "exit 10 mm above the bottom"
    assert label.t.size == 30 mm, "30 mm letters"
}
