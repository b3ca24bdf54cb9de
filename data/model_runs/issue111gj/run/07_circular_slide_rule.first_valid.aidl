# Request: a circular slide rule for the school science club, 3 mm ply discs and a clear
# acrylic cursor, all on one 5 mm Chicago screw (5.2 mm holes at the centre). The base disc
# is 160 mm across and carries the fixed scale D just outside a 120 mm circle; the 120 mm
# inner disc turns on it and carries scale C just inside its rim, so the two scales meet at
# the disc's edge. Each scale is one decade, 1 at the top and running clockwise, a value v at
# 360 deg x log10(v) from the top: ticks every 0.1 from 1.0 to 9.9 (90 ticks), 6 mm long at
# the whole numbers, 4 mm at the halves, 2.5 mm otherwise; the whole numbers 1..9 labelled in
# 4 mm figures. "C" and "D" next to the 1s, "SLIDE RULE" engraved above the pivot. The cursor
# is a 16 mm wide arm from the pivot to 88 mm out, with a hairline engraved down its middle
# from 20 mm to 86 mm.

units mm
thickness 3 mm

def ang(v) = 90 deg - 360 deg * log(v) / log(10)
def tick(k) = 6 if k % 10 == 0 else (4 if k % 10 == 5 else 2.5)

assembly slide_rule {
    solid base {
        body = Circle(center=(0, 0), diameter=160)
        hole pivot { c = Circle(center=(0, 0), diameter=5.2) }
        drawing scale {
            for k in range(90) {
                t = Line(polar((0, 0), 60.5, ang(1 + k * 0.1)), polar((0, 0), 60.5 + tick(k), ang(1 + k * 0.1)))
            }
            ring = Circle(center=(0, 0), radius=70, construction=true)
            for n in range(1, 10) {
                num = Text(str(n), along=ring, angle=ang(n), size=4, valign="middle")
            }
            name = Text("D", along=ring, angle=ang(1) + 6 deg, size=4, valign="middle")
        }
    }

    solid disc {
        body = Circle(center=(0, 0), diameter=120)
        hole pivot { c = Circle(center=(0, 0), diameter=5.2) }
        drawing scale {
            for k in range(90) {
                t = Line(polar((0, 0), 59.5, ang(1 + k * 0.1)), polar((0, 0), 59.5 - tick(k), ang(1 + k * 0.1)))
            }
            ring = Circle(center=(0, 0), radius=50, construction=true)
            for n in range(1, 10) {
                num = Text(str(n), along=ring, angle=ang(n), size=4, valign="middle")
            }
            name = Text("C", along=ring, angle=ang(1) + 6 deg, size=4, valign="middle")
            title = Text("SLIDE RULE", position=(0, 14), size=5, valign="middle")
        }
    }

    solid cursor {
        arm = Slot(start=(0, 0), end=(0, 80), width=16)
        hole pivot { c = Circle(center=(0, 0), diameter=5.2) }
        drawing hairline {
            h = Line((0, 20), (0, 86))
        }
    }

    # flat for cutting: side by side
    RightOf(disc, base, gap=10)
    AlignTop(disc, base)
    RightOf(cursor, disc, gap=10)
    AlignTop(cursor, disc)

    # assembled: stacked on the screw, the cursor turned 30 deg clockwise
    Place(base, position=(0, 0, 0))
    Place(disc, position=(0, 0, 3 mm))
    Place(cursor, position=(0, 0, 6 mm), rotation=(0, 0, -30 deg))

    assert base.body.diameter == 160 mm and disc.body.diameter == 120 mm, "discs 160 and 120"
    assert base.pivot.c.diameter == 5.2 mm and disc.pivot.c.diameter == 5.2 mm and
        cursor.pivot.c.diameter == 5.2 mm, "5.2 mm pivot holes"
    assert len(base.scale.t) == 90 and len(disc.scale.t) == 90, "90 ticks a scale"
    assert len(base.scale.num) == 9 and len(disc.scale.num) == 9, "figures 1..9"
    assert base.scale.t[0].start.x == base.body.center.x, "1 at the top"
    assert base.scale.t[0].length == 6 mm and base.scale.t[5].length == 4 mm and
        base.scale.t[1].length == 2.5 mm, "tick lengths 6, 4, 2.5"
    assert base.scale.t[0].start.y - base.body.center.y > 60 mm, "D outside the 120 circle"
    assert disc.scale.t[0].start.y - disc.body.center.y < 60 mm, "C inside the disc's rim"
    assert cursor.arm.bb.height == 88 mm + 8 mm, "arm to 88 mm out (plus its round end behind the pivot)"
    assert cursor.arm.bb.width == 16 mm, "arm 16 wide"
    assert cursor.hairline.h.length == 66 mm, "hairline from 20 to 86"
}
