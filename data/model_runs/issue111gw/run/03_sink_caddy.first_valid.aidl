# Request: a caddy for the bathroom sink, cut from 3 mm acrylic: an open finger-jointed tray
# 170 x 90 x 45 mm (outside), 10 mm fingers, split by one divider into two equal compartments
# side by side (the soap pump bottle on the left, toothbrushes and paste on the right). Each
# compartment's floor drains through a grid of 6 mm holes, 3 rows of 4 at 14 mm pitch,
# centred in the compartment. "SOAP" and "BRUSHES" engraved in 10 mm capitals on the front
# wall, each centred over its own compartment and halfway up the wall.

import "std/boxes.aidl"

thickness 3 mm

param length = 170 mm, min = 140 mm, max = 240 mm
param width = 90 mm, min = 70 mm, max = 120 mm
param height = 45 mm, min = 30 mm, max = 80 mm
t = 3 mm
drain_d = 6 mm
drain_pitch = 14 mm
comp_x = (length - t) / 4     # a compartment's centre from the tray's middle (inside 164, divider 3)

assembly sink_caddy {
    tray = divider_tray(length=length, width=width, height=height, rows=1, cols=2,
                        thickness=t, finger=10 mm)

    hole drains {
        for side in range(2) {
            for r in range(3) {
                for c in range(4) {
                    d = Circle(center=((2 * side - 1) * comp_x + (c - 1.5) * drain_pitch,
                                       (r - 1) * drain_pitch), diameter=drain_d)
                }
            }
        }
    }
    CenterInside(drains, tray.body.bottom)
    CutInto(drains, tray.body.bottom)

    drawing soap {
        w = Text("SOAP", position=(0, 0), size=10, valign="middle")
    }
    drawing brushes {
        w = Text("BRUSHES", position=(0, 0), size=10, valign="middle")
    }
    soap.bb.center_x == tray.body.front.bb.center_x - comp_x
    brushes.bb.center_x == tray.body.front.bb.center_x + comp_x
    AlignCenterY(soap, tray.body.front)
    AlignCenterY(brushes, tray.body.front)
    CutInto(soap, tray.body.front)
    CutInto(brushes, tray.body.front)

    assert len(drains.d) == 2 and len(drains.d[0]) == 3 and len(drains.d[0][0]) == 4, "two grids of 3 x 4"
    assert drains.d[0][0][0].diameter == 6 mm, "6 mm drain holes"
    assert drains.d[0][0][1].center.x - drains.d[0][0][0].center.x == 14 mm, "14 mm pitch"
    assert tray.body.front.bb.width == 170 mm and tray.body.front.bb.height == 45 mm, "170 long, 45 high outside"
    assert distance(soap, brushes) >= 10 mm, "the two labels apart"
}
