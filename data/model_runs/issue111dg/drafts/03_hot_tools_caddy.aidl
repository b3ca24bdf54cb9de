# Request (bathroom): a caddy for hot hair tools on the bathroom counter, 6 mm MDF,
# finger-jointed closed box 200 long, 100 deep, 140 tall (outside), 12 mm fingers.
# In the top: a 60 x 30 rounded slot for the hair straightener, its centre 50 mm from the
# left end, and a 40 mm round hole for the curling tongs, its centre 50 mm from the right
# end, both on the top's centre line. In the bottom: a row of five 8 mm vent holes 20 mm
# apart, centred. On the front: "HOT TOOLS" engraved filled, bold, 16 mm, centred.

import "std/joints.aidl"

units mm
thickness 6 mm

assembly caddy {
    box = finger_box(length=200 mm, depth=100 mm, height=140 mm, thickness=6 mm,
                     finger=12 mm, closed=true)

    hole straightener {
        s = Slot(center=(0, 0), length=60, width=30)
    }
    AlignCenterY(straightener, box.lid)
    straightener.s.center.x == box.lid.bb.left + 50
    CutInto(straightener, box.lid)

    hole tongs {
        c = Circle(center=(0, 0), diameter=40)
    }
    AlignCenterY(tongs, box.lid)
    tongs.c.center.x == box.lid.bb.right - 50
    CutInto(tongs, box.lid)

    hole vents {
        for i in range(5) {
            v = Circle(center=(i * 20, 0), diameter=8)
        }
    }
    CenterInside(vents, box.bottom)
    CutInto(vents, box.bottom)

    drawing label {
        w = Text("HOT TOOLS", position=(0, 0), size=16, font="sans:Bold", fill=true,
                 valign="middle")
    }
    CenterInside(label, box.front)
    CutInto(label, box.front)

    assert box.front.bb.width == 200 mm, "200 long outside"
    assert box.front.bb.height == 140 mm, "140 tall outside"
    assert box.left.bb.height == 100 mm, "100 deep outside"
    assert straightener.s.length == 60 mm and straightener.s.width == 30 mm, "60 x 30 slot"
    assert tongs.c.diameter == 40 mm, "40 mm tong hole"
    assert len(vents.v) == 5, "five vents"
    assert vents.v[1].center.x - vents.v[0].center.x == 20 mm, "vents 20 apart"
}
