# Encoder dial plate (electronics): a 70 x 70 mm front plate of 3 mm acrylic, corners R4, for a
# rotary encoder or potentiometer. A 7.2 mm hole for the M7 bushing in the middle and a 3.2 mm
# locating-tab hole 8 mm above it. Four M3 screw holes (3.4 mm) 5 mm in from each corner,
# countersunk 6.5 mm. An engraved scale over 270 deg (0 at 225 deg, 10 at -45 deg, clockwise):
# 21 ticks every 13.5 deg from radius 18 mm, the 11 at whole numbers 4 mm long, the 10 halves
# 2 mm long; the numbers 0 to 10 (3 mm high) centred on radius 26 mm; an engraved arc of radius
# 16 mm along the scale; "GAIN" (3 mm high) centred 25 mm below the middle.
units mm
thickness 3 mm

W = 70 mm
r_tick = 18 mm
r_num = 26 mm

def angle_of(v) = 225 deg - v * 27 deg

solid panel {
    body = RoundedRectangle(center=(0, 0), width=W, height=W, corner_radius=4)

    hole shaft { c = Circle(center=(0, 0), diameter=7.2) }
    hole pin { c = Circle(center=(0, 8), diameter=3.2) }

    hole screw { c = Circle(center=(-30, -30), diameter=3.4) }
    corners = CornerPattern(screw, body, inset=5)
    Countersink(screw, diameter=6.5)

    drawing scale {
        for i in range(21) {
            tick = Line(polar((0, 0), r_tick, 225 deg - i * 13.5 deg),
                        polar((0, 0), r_tick + (4 if i % 2 == 0 else 2), 225 deg - i * 13.5 deg))
            if i % 2 == 0 {
                num = Text(str(i // 2), polar((0, 0), r_num, 225 deg - i * 13.5 deg), size=3, valign="middle")
            }
        }
        track = Arc(center=(0, 0), radius=16, start_angle=-45 deg, end_angle=225 deg)
        name = Text("GAIN", (0, -25), size=3, valign="middle")
    }

    assert body.bb.width == 70 mm and body.bb.height == 70 mm, "plate 70 x 70"
    assert distance(pin.c.center, shaft.c.center) == 8 mm, "locating hole 8 mm from the bushing"
    assert len(corners) == 4, "four screws"
    assert screw.c.center.x - body.bb.left == 5 mm and screw.c.center.y - body.bb.bottom == 5 mm, "screws 5 mm in"
    assert len(scale.tick) == 21, "21 ticks"
    assert len(scale.num) == 11, "numbers 0 to 10"
}
