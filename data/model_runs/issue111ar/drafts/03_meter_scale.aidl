# Request (electronics): a replacement scale for a small moving-coil panel meter, re-labelled
# 0-15 V DC. 1.5 mm white acrylic, 64 x 56 mm with 3 mm corner radii. The needle pivots on the
# plate's centre line 8 mm above the bottom edge; the plate has a U-notch for the pivot bearing,
# 10 mm wide, open at the bottom edge and rounded about the pivot. Two 2.2 mm mounting holes
# level with the pivot, 54 mm apart. The scale spans 90 degrees, symmetric about the vertical,
# 0 V on the left: an engraved baseline arc of radius 30 mm about the pivot and 31 ticks (every
# 0.5 V) running outward from it, 2 mm long, 3.5 mm at every whole volt, 5 mm at 0, 5, 10 and 15;
# the numbers 0, 5, 10, 15 (3 mm, upright) centred on radius 38.5 mm at their ticks; a 6 mm "V"
# on the centre line 16 mm above the pivot and "DC" (3 mm) under it.

thickness 1.5 mm

param volts = 15, min = 5, max = 30
param span = 90 deg, min = 60 deg, max = 100 deg

r_scale = 30 mm
r_num = 38.5 mm
pivot_y = -20 mm        # the pivot sits at (0, pivot_y): the plate is placed about it
def ang(v) = 90 deg + span / 2 - v * span / volts
def tick_len(j) = 5 mm if j % 10 == 0 else (3.5 mm if j % 2 == 0 else 2 mm)

solid scale_plate {
    body = RoundedRectangle(center=(0, pivot_y - 8 + 28), width=64, height=56, corner_radius=3)
    hole notch {
        bearing = Circle(center=(0, pivot_y), diameter=10)
        mouth = Rectangle(center=(0, pivot_y - 5), width=10, height=10, overrun=true)
    }
    hole mounts {
        a = Circle(center=(-27, pivot_y), diameter=2.2)
        b = Circle(center=(27, pivot_y), diameter=2.2)
    }
    drawing dial {
        base = Arc(center=(0, pivot_y), radius=r_scale, start_angle=ang(volts), end_angle=ang(0))
        for j in range(2 * volts + 1) {
            t = Line((r_scale * cos(ang(j / 2)), pivot_y + r_scale * sin(ang(j / 2))),
                     ((r_scale + tick_len(j)) * cos(ang(j / 2)),
                      pivot_y + (r_scale + tick_len(j)) * sin(ang(j / 2))))
        }
        for k in range(4) {
            n = Text(str(5 * k), (r_num * cos(ang(5 * k)), pivot_y + r_num * sin(ang(5 * k))),
                     size=3, valign="middle")
        }
        unit = Text("V", (0, pivot_y + 16), size=6, valign="middle")
        dc = Text("DC", (0, pivot_y + 9.5), size=3, valign="middle")
    }
    Fixed(body)

    assert abs(body.width - 64 mm) < 0.01 mm and abs(body.height - 56 mm) < 0.01 mm, "64 x 56"
    assert abs(notch.bearing.center.y - body.bb.bottom - 8 mm) < 0.01 mm, "pivot 8 above the bottom"
    assert abs(notch.bearing.center.x - body.center.x) < 0.01 mm, "pivot on the centre line"
    assert abs(mounts.b.center.x - mounts.a.center.x - 54 mm) < 0.01 mm, "mounts 54 apart"
    assert len(dial.t) == 31, "31 ticks"
    assert dial.t[0].start.x < dial.t[30].start.x, "0 V on the left"
    assert abs(ang(0) - ang(volts) - 90 deg) < 0.01 deg, "90 degree span"
    assert abs(dial.t[2].length - 3.5 mm) < 0.01 mm and abs(dial.t[10].length - 5 mm) < 0.01 mm and abs(dial.t[1].length - 2 mm) < 0.01 mm, "tick lengths"
    assert dial.bb.top < body.bb.top - 2 mm and dial.bb.left > body.bb.left + 2 mm and dial.bb.right < body.bb.right - 2 mm, "scale on the plate"
}
