# Request (science): a trundle wheel for the school's field-measuring lessons, from 6 mm
# ply, cut with my laser's 0.15 mm kerf allowed for.
# - The wheel: exactly 1 m round (318.31 mm across), a 6.5 mm axle hole (M6 bolt), five
#   spoke windows between 45 and 125 mm radius, each 50 deg wide with R6 corners, centred
#   between the 0 mark and the next ones; a 6 mm hole for the click peg 120 mm out at the 0
#   mark (straight up); ten engraved ticks every 100 mm of rim (36 deg), 8 mm long, 2 mm
#   in from the rim, numbered 0, 10, ... 90 (cm) just inside them; "1 m" filled-engraved
#   over the axle.
# - A fork of two cheeks 22 mm apart (the wheel in the middle on 8 mm spacers, and a 22 mm
#   broom handle clamped between their tops by two M5 bolts, 5.5 mm holes 270 and 310 mm
#   above the axle). Each cheek: the hull of a 36 mm circle at the axle and a 40 mm circle
#   320 mm above it; a mortise for the spacer plate 195 mm above the axle (clear of the
#   rim); two 4 mm holes 14 mm apart 128 mm above the axle for the cable-tie clicker.
# - A spacer plate 40 mm wide joining the cheeks, a 20 mm tenon through each cheek.
# "TRUNDLE WHEEL 1 m" filled-engraved along each cheek.

units mm
thickness 6 mm
kerf 0.15 mm
import "std/joints.aidl"

t = 6 mm
R = 1000 mm / (2 * pi)      # the wheel's radius: 1 m round
gap = 22 mm                 # between the cheeks
spacer_y = 195 mm           # the spacer's middle above the axle

def cheek() -> solid {
    # x along the rolling direction, y up from the axle
    outline = Hull(Circle(center=(0, 0), diameter=36), Circle(center=(0, 320), diameter=40))
    hole axle { c = Circle(center=(0, 0), diameter=6.5) }
    hole bolt_low { c = Circle(center=(0, 270), diameter=5.5) }
    hole bolt_high { c = Circle(center=(0, 310), diameter=5.5) }
    hole tie_a { c = Circle(center=(-7, 128), diameter=4) }
    hole tie_b { c = Circle(center=(7, 128), diameter=4) }
    mortise = tab_and_slot(part="slot", length=40, thickness=t, tabs=1, tab=20, screw=0,
                           rotation=0, cx=0, cy=spacer_y)
    drawing label {
        word = Text("TRUNDLE WHEEL 1 m", position=(0, 60), size=8, rotation=90,
                    anchor="start", valign="middle", font="sans:Bold", fill=true)
    }
}

assembly trundle {
    solid wheel {
        rim = Circle(center=(0, 0), radius=R)
        hole axle { c = Circle(center=(0, 0), diameter=6.5) }
        hole peg { c = Circle(center=(0, 120), diameter=6) }
        hole win {
            w = Sector(center=(0, 0), radius=125, start_angle=90 deg + 36 deg - 25 deg,
                       end_angle=90 deg + 36 deg + 25 deg, inner_radius=45)
            Fillet(6)
        }
        windows = CircularPattern(win, 5, rim.center)
        drawing marks {
            for k in range(10) {
                tick = Line(((R - 10) * cos(90 deg - k * 36 deg), (R - 10) * sin(90 deg - k * 36 deg)),
                            ((R - 2) * cos(90 deg - k * 36 deg), (R - 2) * sin(90 deg - k * 36 deg)))
            }
            ring = Circle(center=(0, 0), radius=R - 17, construction=true)
            for k in range(10) {
                num = Text(str(k * 10), along=ring, angle=90 deg - k * 36 deg, size=8,
                           valign="middle")
            }
            metre = Text("1 m", position=(0, 22), size=12, valign="middle", font="sans:Bold",
                         fill=true)
        }
    }

    left = cheek()
    right = cheek()

    solid spacer {
        # x along the rolling direction, y across between the cheeks
        plate = Rectangle(center=(0, 0), width=40, height=gap + 2 * t)
        end_a = tab_and_slot(part="tab", length=40, thickness=t, tabs=1, tab=20, screw=0,
                             rotation=0, cx=0, cy=gap / 2 + t)
        end_b = tab_and_slot(part="tab", length=40, thickness=t, tabs=1, tab=20, screw=0,
                             rotation=180, cx=0, cy=-(gap / 2 + t))
    }

    # flat on the sheet
    RightOf(left, wheel, gap=8)
    AlignBottom(left, wheel)
    RightOf(right, left, gap=8)
    AlignBottom(right, wheel)
    RightOf(spacer, right, gap=8)
    AlignBottom(spacer, wheel)

    # rolling: the wheel upright in the plane y = 0, the cheeks each side, the spacer across
    Place(wheel, position=(0, t / 2, R), face="front", up="up")
    Place(left, position=(0, -gap / 2, R), face="front", up="up")
    Place(right, position=(0, gap / 2, R), face="back", up="up")
    Place(spacer, position=(0, 0, R + spacer_y - t / 2), face="up", up="back")

    # the request's numbers
    assert abs(2 * pi * wheel.rim.radius - 1000 mm) < 0.01 mm, "1 m round"
    assert len(wheel.windows) == 5, "five windows"
    assert len(wheel.marks.tick) == 10 and len(wheel.marks.num) == 10, "ten ticks"
    assert wheel.peg.c.center.y - wheel.rim.center.y == 120 mm, "peg 120 out"
    assert spacer_y - t / 2 - R >= 20 mm, "spacer clear of the rim"
    assert spacer.plate.height - 2 * t == 22 mm, "cheeks 22 apart"
    assert gap - t == 2 * 8 mm, "8 mm spacers each side of the wheel"
    assert left.bolt_high.c.center.y - left.axle.c.center.y == 310 mm, "top bolt 310 up"
    assert left.tie_b.c.center.x - left.tie_a.c.center.x == 14 mm, "tie holes 14 apart"
}
