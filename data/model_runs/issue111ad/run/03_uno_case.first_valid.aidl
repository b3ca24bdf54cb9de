# Electronics: a finger-jointed case from 3 mm plywood for the Arduino Uno of my
# weather station. The Uno board is 68.6 x 53.4 mm; its 4 mounting holes (3.2 mm,
# on 5 mm standoffs) sit at (14.0, 2.5), (15.3, 50.7), (66.1, 7.6) and
# (66.1, 35.5) mm from the board's bottom-left corner. 2 mm clearance all round,
# 28 mm inside from floor to lid, so the box is 78.6 x 63.4 x 34 mm outside.
# Openings in the left wall for the USB-B socket (13 wide x 12 tall, centred at
# y 38.1) and the barrel jack (10 x 12, centred at y 7.6), both sitting on the
# board's top face. A hex vent in the lid. A 6 mm hole for the sensor cable in
# the middle of the right wall. "WEATHER STATION" engraved 5 mm high in the middle
# of the front wall.

import "std/enclosures.aidl"

units mm
thickness 3 mm

param depth = 28 mm, min = 20, max = 60

assembly uno_case {
    k = board_enclosure(width=68.6 mm, height=53.4 mm, depth=depth, thickness=3 mm,
                        clearance=2 mm,
                        holes=[[14.0, 2.5], [15.3, 50.7], [66.1, 7.6], [66.1, 35.5]],
                        hole_d=3.2 mm, standoff=5 mm,
                        ports=[["left", 38.1, 13, 12], ["left", 7.6, 10, 12]],
                        vent="hex", finger=10 mm)

    hole gland {
        c = Circle(center=(0, 0), diameter=6)
    }
    CenterInside(gland, k.right)
    CutInto(gland, k.right)

    drawing label {
        t = Text("WEATHER STATION", position=(0, 0), size=5, valign="middle")
    }
    CenterInside(label, k.front)
    CutInto(label, k.front)

    assert k.length == 78.6 mm, "78.6 long outside"
    assert k.wide == 63.4 mm, "63.4 wide outside"
    assert k.tall == 34 mm, "34 tall outside"
    assert gland.c.diameter == 6 mm, "6 mm cable hole"
}
