# 180-degree protractor, 3 mm clear acrylic: a half disc of radius 80 mm on a 160 x 10 mm
# base strip below its diameter (overall 160 x 90 mm). Scale center at the middle of the
# diameter, marked by a 3 mm hole. Engraved ticks every degree, ending 1 mm inside the arc
# edge (r 79 mm): 3 mm long, 5 mm every 5 degrees, 8 mm every 10 degrees; numbers 0..180 every
# 10 degrees, 3.5 mm tall, centered at r 64 mm, turned to read from the center. A half-ring
# window from r 25 to r 45 mm between 20 and 160 degrees.

units mm
thickness 3 mm

param r = 80 mm, min = 50 mm, max = 150 mm
param strip = 10 mm, min = 5 mm, max = 20 mm

solid protractor {
    half = Sector(center=(0, 0), radius=r, start_angle=0 deg, end_angle=180 deg)
    base = Rectangle(center=(0, -strip / 2), width=2 * r, height=strip)

    hole pivot {
        c = Circle(center=(0, 0), diameter=3)
    }

    hole window {
        w = Sector(center=(0, 0), radius=45, start_angle=20 deg, end_angle=160 deg, inner_radius=25)
    }

    drawing scale {
        for i in range(181) {
            len_i = 8 mm if i % 10 == 0 else (5 mm if i % 5 == 0 else 3 mm)
            tick = Line(((r - 1 mm) * cos(i * 1 deg), (r - 1 mm) * sin(i * 1 deg)),
                        ((r - 1 mm - len_i) * cos(i * 1 deg), (r - 1 mm - len_i) * sin(i * 1 deg)))
        }
        for k in range(19) {
            num = Text(str(k * 10), position=(64 mm * cos(k * 10 deg), 64 mm * sin(k * 10 deg)),
                       size=3.5, valign="middle", rotation=k * 10 - 90)
        }
    }

    assert abs(self.bb.width - 160 mm) < 0.01 mm, "160 mm wide"
    assert abs(self.bb.height - 90 mm) < 0.01 mm, "90 mm tall"
    assert len(scale.tick) == 181, "a tick every degree, 0..180"
    assert len(scale.num) == 19, "numbers every 10 degrees"
    assert abs(scale.tick[10].length - 8 mm) < 0.001 mm, "10-degree ticks 8 mm"
    assert abs(scale.tick[5].length - 5 mm) < 0.001 mm, "5-degree ticks 5 mm"
    assert abs(scale.tick[1].length - 3 mm) < 0.001 mm, "1-degree ticks 3 mm"
}
