# Dice tray for board games, 3 mm plywood: an open finger-jointed box (no lid), 160 x 120 mm
# inside and 35 mm deep inside, 10 mm fingers.
# A 30 mm diameter half-round thumb notch cut into the front panel, centred on its top edge.
# "ROLL" in Noto Sans Bold, 20 mm cap height, fill-engraved, centred on the bottom panel.
import "std/joints.aidl"
units mm
thickness 3 mm

assembly dice_tray {
    box = finger_box(length=160 mm, depth=120 mm, height=35 mm, thickness=3 mm, finger=10 mm,
                     closed=false, outside=false)

    hole notch {
        c = Circle(center=(0, 0), diameter=30)
    }
    Coincident(notch.c.center, box.front.outline.top.midpoint)
    CutInto(notch, box.front)

    drawing roll {
        t = Text("ROLL", position=(0, 0), size=20, font="sans:Bold", valign="middle", fill=true)
    }
    CenterInside(roll, box.bottom.outline)
    CutInto(roll, box.bottom)

    # the request's numbers (outer = inside + two thicknesses; one in height: open top)
    assert box.bottom.outline.width == 160 mm + 2 * 3 mm, "160 mm inside"
    assert box.bottom.outline.height == 120 mm + 2 * 3 mm, "120 mm inside"
    assert box.front.outline.height == 35 mm + 3 mm, "35 mm deep inside"
    assert notch.c.diameter == 30 mm, "30 mm notch"
    assert notch.c.center.y == box.front.outline.bb.top, "notch centred on the top edge"
    assert notch.c.center.x == box.front.outline.bb.center_x, "notch in the middle"
    assert abs(roll.bb.center_x - box.bottom.outline.bb.center_x) < 0.01 mm, "ROLL centred"
    assert abs(roll.bb.center_y - box.bottom.outline.bb.center_y) < 0.01 mm, "ROLL centred"
}
