# Request: a wall-hung case for my little weather display (a 0.96-inch OLED, an ESP32-C3 mini
# board and a BME280 sensor), as a sandwich of four 3 mm acrylic layers, 76 x 52 mm with 5 mm
# corner radii, held by four M3 countersunk screws 5 mm in from the sides (x and y) with M3
# nuts in hexagonal traps in the back. From the front: (1) the front plate with a 23 x 12 mm
# display window (R1 corners) centred 16 mm left of the middle and 3 mm above it, five vent
# slots 2 x 14 mm on a 4 mm pitch centred 18 mm right of the middle for the sensor, the screw
# holes countersunk for 6 mm heads, and "WEATHER" engraved 4 mm high, centred under the
# window with its baseline 10 mm below the middle; (2) and (3) two spacer frames with a
# 62 x 32 mm pocket (R3 corners) for the boards and a 13 mm wide notch through the bottom
# edge for the USB-C plug, centred 18 mm right of the middle; (4) the back with the nut traps
# and a keyhole (8 mm head, 4 mm slot, 10 mm up) whose head is 6 mm above the middle, to hang
# it on a screw.

import "std/fasteners.aidl"
import "std/plates.aidl"

thickness 3 mm

t = 3 mm
W = 76 mm
H = 52 mm
R = 5 mm
inset = 5 mm

def spacer() -> solid {
    body = RoundedRectangle(center=(0, 0), width=W, height=H, corner_radius=R)
    Fixed(body)
    hole pocket { p = RoundedRectangle(center=(0, 0), width=62, height=32, corner_radius=3) }
    hole usb { n = Rectangle(center=(18, -H / 2 + 2), width=13, height=24) }
    # FIX after the first valid program: the notch is meant to open into the pocket (W0508)
    AllowOverlap(pocket, usb)
    screw = clearance_hole(size=3)
    corners = CornerPattern(screw, body, inset=inset)
}

assembly weather_case {
    solid front {
        body = RoundedRectangle(center=(0, 0), width=W, height=H, corner_radius=R)
        Fixed(body)
        hole window { w = RoundedRectangle(center=(-16, 3), width=23, height=12, corner_radius=1) }
        hole vents {
            for i in range(5) {
                v = Slot(center=(18 + (i - 2) * 4, 0), length=14, width=2, rotation=90 deg)
            }
        }
        screw = clearance_hole(size=3)
        corners = CornerPattern(screw, body, inset=inset)
        Countersink(corners, diameter=6 mm)
        drawing label {
            name = Text("WEATHER", position=(-16, -10), size=4)
        }
    }

    upper = spacer()
    lower = spacer()

    solid back {
        body = RoundedRectangle(center=(0, 0), width=W, height=H, corner_radius=R)
        Fixed(body)
        nut = nut_trap(size=3)
        nuts = CornerPattern(nut, body, inset=inset)
        hang = keyhole(head=8 mm, slot_width=4 mm, length=10 mm, direction=90 deg, cx=0 mm,
                       cy=6 mm)
    }

    # flat: the four layers in a row, front first
    RightOf(upper, front, gap=5)
    RightOf(lower, upper, gap=5)
    RightOf(back, lower, gap=5)
    AlignCenterY(upper, front)
    AlignCenterY(lower, front)
    AlignCenterY(back, front)

    # assembled: the back on the wall side at z = 0, the front on top
    Place(back, position=(0, 0, 0), face="up")
    Place(lower, position=(0, 0, t), face="up")
    Place(upper, position=(0, 0, 2 * t), face="up")
    Place(front, position=(0, 0, 3 * t), face="up")

    assert front.body.bb.width == 76 mm and front.body.bb.height == 52 mm
    assert front.screw.c.center.x - front.body.bb.left == 5 mm, "screws 5 mm in (x)"
    assert front.screw.c.center.y - front.body.bb.bottom == 5 mm, "screws 5 mm in (y)"
    assert front.window.w.center.x - front.body.center.x == -16 mm
    assert front.window.w.center.y - front.body.center.y == 3 mm
    assert len(front.vents.v) == 5
    assert front.label.name.position.y - front.body.center.y == -10 mm
    assert upper.pocket.p.bb.width == 62 mm and upper.pocket.p.bb.height == 32 mm
    assert upper.usb.n.center.x - upper.body.center.x == 18 mm
    assert back.hang.head_hole.center.y - back.body.center.y == 6 mm
}
