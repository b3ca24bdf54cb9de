# Request (electronics): a faceplate for my wired doorbell: a 16 mm anti-vandal push button
# with a 5 mm "heard you" LED above it, house number 17. Two layers of 3 mm acrylic, each
# 70 wide x 130 tall with 10 mm rounded corners, stacked (the back layer is a second colour
# that shows through the number).
# Front layer:
# - the button's 16.2 mm hole centred 35 mm above the bottom edge;
# - the LED's 5 mm hole 25 mm above the button's centre;
# - "17" cut right through in bold sans, 32 mm tall, its middle 28 mm above the plate's centre;
# - "PLEASE RING" engraved along a 13 mm radius arc over the button;
# - two M4 countersunk screw holes (4.5 mm, 9 mm heads) on the centre line, 12 mm from the
#   top and bottom edges.
# Back layer: the same screw holes (no countersink), a 24 mm opening behind the button for
# its nut and wires, an 8 mm opening behind the LED for its holder.

units mm
thickness 3 mm

w = 70 mm
h = 130 mm
btn_up = 35 mm
led_above = 25 mm
screw_in = 12 mm

assembly doorbell {
    solid front {
        body = RoundedRectangle(center=(0, 0), width=w, height=h, corner_radius=10)
        hole button { c = Circle(center=(0, -h / 2 + btn_up), diameter=16.2) }
        hole led { c = Circle(center=(0, -h / 2 + btn_up + led_above), diameter=5) }
        hole number {
            t = Text("17", position=(0, 28), size=32, font="sans:Bold", valign="middle")
        }
        hole screws {
            top = Circle(center=(0, h / 2 - screw_in), diameter=4.5)
            bottom = Circle(center=(0, -h / 2 + screw_in), diameter=4.5)
        }
        Countersink(screws, diameter=9)
        drawing ring_label {
            arc = Circle(center=(0, -h / 2 + btn_up), radius=13, construction=true)
            t = Text("PLEASE RING", along=arc, size=3.5)
        }
    }

    solid back {
        body = RoundedRectangle(center=(0, 0), width=w, height=h, corner_radius=10)
        hole nut { c = Circle(center=(0, -h / 2 + btn_up), diameter=24) }
        hole led_holder { c = Circle(center=(0, -h / 2 + btn_up + led_above), diameter=8) }
        hole screws {
            top = Circle(center=(0, h / 2 - screw_in), diameter=4.5)
            bottom = Circle(center=(0, -h / 2 + screw_in), diameter=4.5)
        }
    }

    RightOf(back, front, gap=10)
    AlignTop(back, front)
    Place(back, position=(0, 0, 0))
    Place(front, position=(0, 0, 3))

    assert front.button.c.center.y - front.body.bb.bottom == 35 mm, "button 35 mm up"
    assert front.led.c.center.y - front.button.c.center.y == 25 mm, "LED 25 mm over the button"
    assert front.body.bb.top - front.screws.top.center.y == 12 mm, "top screw 12 mm in"
    assert front.screws.bottom.center.y - front.body.bb.bottom == 12 mm, "bottom screw 12 mm in"
    assert front.number.t.position.y - front.body.center.y == 28 mm, "number 28 mm over centre"
    assert distance(front.number, front.screws) >= 4 mm, "number clear of the screw heads"
    assert distance(front.number, front.led) >= 4 mm, "number clear of the LED"
    assert distance(front.ring_label, front.led) >= 1.5 mm, "label clear of the LED"
    assert front.number.bb.width <= w - 16 mm, "number inside the plate"
    assert back.nut.c.center.y == front.button.c.center.y, "nut opening behind the button"
}
