# Request (electronics): a 12-key macropad case for Cherry MX switches, a stack of three
# laser-cut layers held by four M3 screws. All three are 96 x 86 mm with 4 mm corner radius and
# an M3 clearance hole 5 mm in from both edges at each corner.
# - Switch plate, 1.5 mm acrylic: 4 columns x 3 rows of 14.0 x 14.0 mm square cut-outs at the
#   19.05 mm key pitch, the grid centred left-right, the bottom row's centres 16 mm above the
#   plate's bottom edge; "MACROPAD" engraved 6 mm tall, centred in the strip above the keys.
# - Spacer frame, 3 mm acrylic: an 8 mm wall all round, with a 12 mm wide notch through the
#   middle of the top wall for the USB cable.
# - Bottom plate, 3 mm acrylic: plain, with "12 KEYS / M3 x 10" engraved in the middle.

import "std/fasteners.aidl"

param pitch = 19.05 mm, min = 18 mm, max = 20 mm
param cols = 4, min = 2, max = 5
param rows = 3, min = 1, max = 4

def pad_plate() -> solid {
    body = RoundedRectangle(center=(0, 0), width=96, height=86, corner_radius=4)
    h = clearance_hole(size=3)
    Fixed(body)
    screws = CornerPattern(h, body, inset=5)
}

assembly macropad {
    solid top {
        thickness 1.5 mm
        plate = pad_plate()
        hole key {
            k = Rectangle(center=(-(cols - 1) * pitch / 2, -43 + 16), width=14, height=14)
        }
        keys = GridPattern(key, rows, cols, pitch)
        drawing label {
            word = Text("MACROPAD", (0, 30), size=6, valign="middle")
        }
        # the label centred in the strip between the top row of keys and the plate's top edge
        label.bb.center_y == (keys[rows * cols - 1].bb.top + plate.body.bb.top) / 2
        AlignCenterX(label, plate.body)
    }

    solid frame {
        thickness 3 mm
        plate = pad_plate()
        hole window {
            w = Rectangle(center=(0, 0), width=96 - 2 * 8, height=86 - 2 * 8)
        }
        hole usb {
            n = Rectangle(center=(0, 43 - 4), width=12, height=10)
        }
        # FIX after the first valid program: the notch is meant to open into the window (W0508)
        AllowOverlap(window, usb)
    }

    solid bottom {
        thickness 3 mm
        plate = pad_plate()
        drawing note {
            a = Text("12 KEYS", (0, 4), size=6)
            b = Text("M3 x 10", (0, -8), size=6)
        }
    }

    RightOf(frame, top, gap=8)
    RightOf(bottom, frame, gap=8)
    AlignCenterY(frame, top)
    AlignCenterY(bottom, top)
    Place(bottom, position=(0, 0, 0))
    Place(frame, position=(0, 0, 3))
    Place(top, position=(0, 0, 6))

    # the request's numbers
    assert len(top.keys) == 12, "12 keys"
    assert top.key.k.width == 14 mm and top.key.k.height == 14 mm, "14 x 14 cut-outs"
    assert top.keys[1].k.center.x - top.keys[0].k.center.x == 19.05 mm, "key pitch across"
    assert top.keys[4].k.center.y - top.keys[0].k.center.y == 19.05 mm, "key pitch up"
    assert top.keys[0].k.center.y - top.plate.body.bb.bottom == 16 mm, "bottom row 16 mm up"
    assert abs((top.keys[0].bb.left + top.keys[3].bb.right) / 2 - top.plate.body.bb.center_x) < 0.001 mm,
        "grid centred left-right"
    assert top.plate.body.bb.width == 96 mm and top.plate.body.bb.height == 86 mm, "96 x 86"
    assert top.plate.screws[0].c.center.x - top.plate.body.bb.left == 5 mm, "screws 5 mm in"
    assert top.plate.screws[0].c.center.y - top.plate.body.bb.bottom == 5 mm, "screws 5 mm in"
    assert frame.window.w.bb.left - frame.plate.body.bb.left == 8 mm, "8 mm wall"
    assert frame.usb.n.width == 12 mm, "12 mm USB notch"
}
