# Request (office): a "phone jail" for the meeting-room table: everyone drops their phone in
# at the start. 3 mm ply lift-off-lid box, 160 x 110 x 90 mm outside. In the lid a drop slot
# 90 x 14 mm with round ends, centred left-right, its centre 15 mm below the lid's centre;
# "PHONE JAIL" engraved filled (sans bold, 12 mm caps) centred above the slot, its baseline
# 12 mm above the slot's top edge. In the front a barred window: a 100 x 50 mm opening centred
# on the front, divided by 4 bars 6 mm wide into 5 equal openings.

units mm
thickness 3 mm

import "std/boxes.aidl"

param bars = 4, min = 2, max = 8
bar_w = 6 mm
win_w = 100 mm
win_h = 50 mm
gap_w = (win_w - bars * bar_w) / (bars + 1)

assembly phone_jail {
    box = lid_box(length=160 mm, width=110 mm, height=90 mm)

    hole drop {
        s = Slot(center=(0, 0), length=90, width=14)
    }
    AlignCenterX(drop, box.lid)
    VerticalDistance(drop.s.center, box.lid.bb.center, 15)
    CutInto(drop, box.lid)

    drawing name {
        t = Text("PHONE JAIL", position=(0, 20), size=12, font="sans:Bold", fill=true)
    }
    AlignCenterX(name, box.lid)
    VerticalDistance(drop.bb.top, name.t.position, 12)
    CutInto(name, box.lid)

    hole window {
        for i in range(bars + 1) {
            pane = Rectangle(center=(-win_w / 2 + gap_w / 2 + i * (gap_w + bar_w), 0),
                             width=gap_w, height=win_h)
        }
    }
    CenterInside(window, box.body.front)
    CutInto(window, box.body.front)

    # the request's numbers
    assert abs(drop.s.length - 90 mm) < 0.001 mm and abs(drop.s.width - 14 mm) < 0.001 mm, "slot 90 x 14"
    assert abs(box.lid.bb.center_y - drop.s.center.y - 15 mm) < 0.001 mm, "slot 15 below the lid centre"
    assert abs(name.t.position.y - drop.bb.top - 12 mm) < 0.001 mm, "name 12 above the slot"
    assert abs(window.bb.width - 100 mm) < 0.001 mm and abs(window.bb.height - 50 mm) < 0.001 mm, "window 100 x 50"
    assert len(window.pane) == 5, "4 bars make 5 openings"
    assert abs(window.pane[1].bb.left - window.pane[0].bb.right - 6 mm) < 0.001 mm, "bars 6 wide"
    assert abs(box.lid.bb.width - 160 mm) < 0.001 mm and abs(box.lid.bb.height - 110 mm) < 0.001 mm, "lid 160 x 110"
    assert name.bb.top <= box.lid.bb.top - 5 mm, "name on the lid"
}
