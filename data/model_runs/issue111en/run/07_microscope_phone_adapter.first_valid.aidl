# Request: a phone adapter for the school microscope's eyepiece (30 mm outside), from 3 mm
# clear acrylic, three layers glued. The phone plate: 170 x 80 mm, R8 corners, a 16 mm camera
# window whose centre is 30 mm from the plate's left end on its middle line; engraved
# crosshair ticks (6 mm long, 2 mm out from the window's edge) at 0, 90, 180 and 270 deg;
# four 6 x 4 mm notches for two rubber bands, in the top and bottom edges at 65 and 125 mm
# from the window's centre; an engraved scale along the bottom edge for noting where the
# phone's edge sits: a tick every 5 mm from the window's centre to 130 mm, 4 mm long at each
# 10 mm and 2.5 mm otherwise, starting 6 mm above the edge, numbered every 20 mm (3 mm
# figures); "MICROSCOPE CAM" (6 mm) and "EYEPIECE 30 mm" (4 mm) engraved on the plate's right
# part. Under the window, two collar rings 50 mm across with a 30.6 mm bore (30 mm eyepiece
# + 0.6 clearance), glued concentric with the window.

import "std/shapes.aidl"

thickness 3 mm

PW = 170 mm
PH = 80 mm
WX = -PW / 2 + 30 mm    # window centre x on the plate
WIN = 16 mm

assembly phone_adapter {
    solid plate {
        body = RoundedRectangle(center=(0, 0), width=PW, height=PH, corner_radius=8)
        hole camera { c = Circle(center=(WX, 0), diameter=WIN) }
        hole bands {
            for dx in [65 mm, 125 mm] {
                top = Rectangle(center=(WX + dx, PH / 2), width=6, height=8, overrun=true)
                bottom = Rectangle(center=(WX + dx, -PH / 2), width=6, height=8,
                                   overrun=true)
            }
        }
        drawing marks {
            for a in [0 deg, 90 deg, 180 deg, 270 deg] {
                tick = Line(polar((WX, 0), WIN / 2 + 2 mm, a), polar((WX, 0), WIN / 2 + 8 mm, a))
            }
            for k in range(27) {
                s = Line((WX + k * 5 mm, -PH / 2 + 6 mm),
                         (WX + k * 5 mm, -PH / 2 + 6 mm + (4 mm if k % 2 == 0 else 2.5 mm)))
            }
            for k in range(0, 27, 4) {
                n = Text(str(k * 5), position=(WX + k * 5 mm, -PH / 2 + 12 mm), size=3)
            }
            name = Text("MICROSCOPE CAM", position=(35, 12), size=6)
            fit = Text("EYEPIECE 30 mm", position=(35, 2), size=4)
        }
        assert body.width == 170 mm and body.height == 80 mm
        assert camera.c.center.x - body.bb.left == 30 mm, "window 30 from the left end"
        assert camera.c.diameter == 16 mm
        assert len(bands.top) == 2 and len(bands.bottom) == 2, "four band notches"
        assert bands.top[1].center.x - camera.c.center.x == 125 mm
        assert len(marks.s) == 27 and marks.s[26].start.x - camera.c.center.x == 130 mm
        assert marks.s[0].start.y - body.bb.bottom == 6 mm
    }
    lower_ring = washer(outer=50 mm, inner=30.6 mm)
    upper_ring = washer(outer=50 mm, inner=30.6 mm)

    RightOf(lower_ring, plate, gap=10)
    AlignTop(lower_ring, plate)
    Below(upper_ring, lower_ring, gap=10)
    AlignLeft(upper_ring, lower_ring)

    # 3D: rings on the eyepiece axis (x = WX, y = 0), the plate on top of them
    Place(lower_ring, position=(WX, 0, 0), face="up")
    Place(upper_ring, position=(WX, 0, 3 mm), face="up")
    Place(plate, position=(0, 0, 6 mm), face="up")

    assert lower_ring.bore.b.diameter == 30.6 mm and lower_ring.ring.diameter == 50 mm
}
