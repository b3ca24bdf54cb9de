# Request: a sunflower thermometer for the garden fence, three glued layers of 6 mm exterior ply.
# The outline: a stem plaque 90 mm wide and 250 mm tall with a 14-petal flower on top (a star,
# tips on R62, notches on R45, tips rounded R5) centred 30 mm above the plaque's top edge.
# A bare glass thermometer tube (6 mm, 160 mm long, a 9 mm bulb at its bottom end, bulb centre
# 30 mm above the plaque's bottom edge) lies in a channel cut through the middle layer: a 6.5 mm
# slot along the tube and a 10 mm pocket for the bulb. The front layer has a 4 mm window
# slot over the column (narrower than the tube, so it holds the tube in) and a 7 mm window
# over the bulb, a Celsius scale on the left (-20 to 50 C at 1.4 mm per degree, -20 C 40 mm
# above the bulb centre; ticks 3.5 mm, 6 mm every 5, 8 mm every 10, numbers every 10) and a
# Fahrenheit scale on the right matching it (ticks every 2 F, longer every 10, numbers every
# 20), "C" and "F" heads; the flower's head engraved as a seed spiral of 1.8 mm dots (the
# sunflower's 137.5 degree spiral). Two countersunk M4 screws through all three layers: one
# in the flower's centre and one 15 mm above the plaque's bottom edge.

import "std/fasteners.aidl"

t = 6 mm
thickness t

# attempt 2: the bulb was 95 mm up with the scale at 1.6 mm per degree from 58 mm above it:
# the scale ran into the flower and past the 160 mm tube (my assert and W0505 / W0513 said so)
BULB_Y = -100          # bulb centre, in the plaque's frame (bottom edge at y = -130)
ZERO_C = BULB_Y + 40   # where -20 C sits
MM_PER_C = 1.4
HEAD = (0, 150)        # the flower's centre

def yc(c) = ZERO_C + (c + 20) * MM_PER_C
def yf(f) = yc((f - 32) * 5 / 9)

def layer(kind=0) -> solid {
    stem = Rectangle(center=(0, -5), width=90, height=250)
    flower = Star(center=HEAD, points=14, outer_radius=62, inner_radius=45, tip_radius=5,
                  rotation=6 deg)  # attempt 2: at 0 a petal's edge met the stem's side 0.4 mm under its corner (W0520)
    top = clearance_hole(size=4, cx=0 mm, cy=150 mm)
    bottom = clearance_hole(size=4, cx=0 mm, cy=-115 mm)
    if kind == 1 {
        hole channel {
            tube = Slot(start=(0, BULB_Y), end=(0, BULB_Y - 4.5 + 160 - 3.25), width=6.5)
            bulb = Circle(center=(0, BULB_Y), diameter=10)
        }
    }
    if kind == 2 {
        hole window {
            col = Slot(start=(0, yc(-22)), end=(0, yc(52)), width=4)
            bulb = Circle(center=(0, BULB_Y), diameter=7)
        }
        drawing celsius {
            for c in range(-20, 51) {
                tick = Line((-4, yc(c)), (-4 - (8 if c % 10 == 0 else (6 if c % 5 == 0 else 3.5)), yc(c)))
            }
            for c in range(-20, 51, 10) {
                num = Text(str(c), position=(-15, yc(c)), size=4.5, anchor="end", valign="middle")
            }
            head = Text("C", position=(-12, yc(50) + 10), size=6, valign="middle")
        }
        drawing fahrenheit {
            for f in range(-4, 123, 2) {
                tick = Line((4, yf(f)), (4 + (7 if f % 10 == 0 else 3.5), yf(f)))
            }
            for f in range(0, 121, 20) {
                num = Text(str(f), position=(14, yf(f)), size=4.5, anchor="start", valign="middle")
            }
            head = Text("F", position=(12, yc(50) + 10), size=6, valign="middle")
        }
        drawing seeds {
            for i in range(8, 121) {
                dot = Circle(center=(2.6 * sqrt(i) * cos(i * 137.508 deg),
                                     150 + 2.6 * sqrt(i) * sin(i * 137.508 deg)),
                             diameter=1.8, fill=true)
            }
        }
        Countersink([top, bottom], diameter=8.5 mm)
    }
    Rigid(self)
}

assembly thermometer {
    back = layer(kind=0)
    middle = layer(kind=1)
    front = layer(kind=2)

    RightOf(middle, back, gap=10)
    AlignTop(middle, back)
    RightOf(front, middle, gap=10)
    AlignTop(front, middle)

    Place(back, position=(0, 0, 0), face="up")
    Place(middle, position=(0, 0, 6), face="up")
    Place(front, position=(0, 0, 12), face="up")

    assert front.stem.width == 90 mm and front.stem.height == 250 mm, "plaque 90 x 250"
    assert front.flower.center.y - front.stem.bb.top == 30 mm, "flower 30 above the plaque"
    assert middle.channel.bulb.center.y - middle.stem.bb.bottom == 30 mm, "bulb 30 above the bottom"
    assert middle.channel.tube.end.y + 3.25 mm - (middle.channel.bulb.center.y - 4.5 mm) == 160 mm, "channel holds a 160 tube"
    assert front.window.col.width < 6 mm, "window narrower than the tube"
    assert len(front.celsius.tick) == 71, "-20 to 50 C, every degree"
    assert front.celsius.tick[70].start.y - front.celsius.tick[0].start.y == 70 * 1.4 mm, "1.4 mm per degree"
    assert front.celsius.tick[0].start.y - front.window.bulb.center.y == 40 mm, "-20 C 40 above the bulb"
    assert front.window.col.end.y > front.celsius.tick[70].start.y, "window reaches past 50 C"
    assert middle.channel.tube.end.y > front.window.col.end.y, "tube reaches past the window"
    assert front.bottom.c.center.y - front.stem.bb.bottom == 15 mm, "bottom screw 15 up"
}
