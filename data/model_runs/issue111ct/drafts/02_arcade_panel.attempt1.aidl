# Request: a one-player arcade controller box for a Raspberry Pi retro console, 3 mm ply,
# finger-jointed, 300 x 160 x 60 mm outside.
# - Top: a joystick (Sanwa-style) with a 24 mm shaft hole and 4 M4 mounting holes on an
#   80 x 40 mm rectangle, its shaft 85 mm left of the top's centre; six 30 mm buttons in the
#   usual arcade curve (top row at (20, 14), (57, 23), (94, 23) mm from the top's centre,
#   bottom row 37 mm below each); START and SELECT: two 24 mm holes at (15, 55) and (-20, 55)
#   with engraved labels 19 mm below their centres; "PLAYER 1" engraved 55 mm below the
#   stick.
# - Back: a USB-B panel socket: 12 x 11 mm opening with two M3 holes 28 mm apart, centred.
# - Bottom: four M3 holes for rubber feet at (+-120, +-50) mm from its centre.

import "std/joints.aidl"

thickness 3 mm

param t = 3 mm, min = 2.5 mm, max = 4 mm
button_d = 30 mm
small_d = 24 mm

assembly controller {
    box = finger_box(length=300 mm, depth=160 mm, height=60 mm, thickness=t, finger=12 mm)

    hole controls {
        stick = Circle(center=(-85, 0), diameter=24)
        for sx in [-40, 40] {
            for sy in [-20, 20] {
                m4 = Circle(center=(-85 + sx, sy), diameter=4.5)
            }
        }
        top_row = [(20, 14), (57, 23), (94, 23)]
        for p in top_row {
            upper = Circle(center=p, diameter=button_d)
            lower = Circle(center=(p[0], p[1] - 37), diameter=button_d)
        }
        start = Circle(center=(15, 55), diameter=small_d)
        select = Circle(center=(-20, 55), diameter=small_d)
    }
    drawing labels {
        start_l = Text("START", position=(15, 36), size=5, valign="middle")
        select_l = Text("SELECT", position=(-20, 36), size=5, valign="middle")
        player = Text("PLAYER 1", position=(-85, -55), size=8, valign="middle")
    }
    At(controls.stick.center, box.lid.bb.center, dx=-85, dy=0)
    At(labels.player.position, box.lid.bb.center, dx=-85, dy=-55)
    CutInto(controls, box.lid)
    CutInto(labels, box.lid)

    hole usb {
        opening = Rectangle(center=(0, 0), width=12, height=11)
        left = Circle(center=(-14, 0), diameter=3.4)
        right = Circle(center=(14, 0), diameter=3.4)
    }
    CenterInside(usb, box.back)
    CutInto(usb, box.back)

    hole feet {
        for fx in [-120, 120] {
            for fy in [-50, 50] {
                f = Circle(center=(fx, fy), diameter=3.4)
            }
        }
    }
    CenterInside(feet, box.bottom)
    CutInto(feet, box.bottom)

    assert box.lid.bb.width == 300 mm and box.lid.bb.height == 160 mm, "outside 300 x 160"
    assert len(controls.upper) + len(controls.lower) == 6, "six buttons"
    assert controls.upper[0].diameter == 30 mm and controls.start.diameter == 24 mm
    assert controls.stick.diameter == 24 mm
    assert len(controls.m4) == 4
    assert controls.upper[0].center.x - controls.stick.center.x == 105 mm
    assert controls.upper[1].center.y - controls.lower[1].center.y == 37 mm
    assert labels.start_l.position.y - controls.start.center.y == -19 mm
    assert usb.right.center.x - usb.left.center.x == 28 mm
    assert len(feet.f) == 4
}
