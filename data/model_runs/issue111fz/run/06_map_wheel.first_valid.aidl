# Request (camping): a map measuring wheel for hill walking, 3 mm clear acrylic, cut with a
# 0.15 mm kerf allowance so the wheel comes out at size. Four pieces on an M4 bolt:
# - a wheel exactly 200 mm round (5 km a turn on a 1:25 000 map), 4.2 mm axle hole; engraved
#   ticks every 4 mm of rim (100 m at 1:25 000): 50 ticks, each 1.5 mm long, every fifth
#   3 mm, every tenth (each km) 5 mm, all reaching to 0.8 mm inside the rim; the km numbers
#   0-4 for 1:25 000 on a ring just inside the ticks, and 0, 2, 4, 6, 8 for 1:50 000 on a
#   smaller ring, 3 mm and 2.5 mm tall;
# - two identical handle cheeks that sandwich the wheel: a tapered grip 110 mm from the axle
#   to the lanyard end (14 mm wide at the axle, 22 mm at the end), a pointer rising from the
#   axle to 27 mm from it over the ticks, a 4.2 mm axle hole and a 5 mm lanyard hole at the
#   end; "OUTER 1:25 000 KM" and "INNER 1:50 000 KM" engraved along the grip, 3 mm;
# - a spacer between the cheeks at the grip, the cheek's outline from 42 mm below the axle
#   to the end (clear of the wheel), with the lanyard hole.

kerf 0.15 mm
thickness 3 mm
t = 3 mm

rim = 200 mm                  # the wheel's circumference
R = rim / pi / 2              # its radius, 31.83 mm
grip = 110 mm

def cheek_outline() = Hull(Circle(center=(0, 0), radius=7 mm),
                           Circle(center=(0, -grip), radius=11 mm))

assembly map_wheel {
    solid wheel {
        disc = Circle(center=(0, 0), radius=R)
        Fixed(disc)
        hole axle { c = Circle(center=(0, 0), diameter=4.2 mm) }
        drawing scale {
            for i in range(50) {
                tick = Line(polar((0, 0), R - 0.8 mm - (5 mm if i % 10 == 0 else
                                  (3 mm if i % 5 == 0 else 1.5 mm)), 90 deg - i * 7.2 deg),
                            polar((0, 0), R - 0.8 mm, 90 deg - i * 7.2 deg))
            }
            km_ring = Circle(center=(0, 0), radius=R - 6.8 mm - 3.5 mm, construction=true)
            half_ring = Circle(center=(0, 0), radius=R - 17 mm, construction=true)
            for k in range(5) {
                km = Text(str(k), along=km_ring, angle=90 deg - k * 72 deg, size=3)
                km50 = Text(str(2 * k), along=half_ring, angle=90 deg - k * 72 deg, size=2.5)
            }
        }
    }

    for j in range(2) {
        solid cheek {
            grip_shape = cheek_outline()
            pointer = Polygon([(-3, 5), (3, 5), (0, 27)])
            Fixed(grip_shape)
            Fixed(pointer)
            hole axle { c = Circle(center=(0, 0), diameter=4.2 mm) }
            hole lanyard { c = Circle(center=(0, -grip), diameter=5 mm) }
            drawing legend {
                outer = Text("OUTER 1:25 000 KM", position=(-3, -75), size=3, rotation=90 deg,
                             valign="middle")
                inner = Text("INNER 1:50 000 KM", position=(3, -75), size=3, rotation=90 deg,
                             valign="middle")
            }
        }
    }

    solid spacer {
        body = Intersect(cheek_outline(),
                         Rectangle(corner=(-15, -grip - 15), opposite=(15, -42)))
        Fixed(body)
        hole lanyard { c = Circle(center=(0, -grip), diameter=5 mm) }
    }

    # flat on the sheet
    RightOf(cheek[0], wheel, gap=10)
    AlignTop(cheek[0], wheel)
    RightOf(cheek[1], cheek[0], gap=10)
    AlignTop(cheek[1], cheek[0])
    RightOf(spacer, cheek[1], gap=10)
    AlignBottom(spacer, cheek[1])

    # in 3D: cheek, wheel and spacer, cheek; the legend of the top cheek looks up, the
    # bottom cheek turned over so its legend looks down
    Place(cheek[0], position=(0, 0, t), face="down", up="back")
    Place(wheel, position=(0, 0, t))
    Place(spacer, position=(0, 0, t))
    Place(cheek[1], position=(0, 0, 2 * t))

    # the request's numbers
    assert abs(pi * wheel.disc.diameter - 200 mm) <= 0.001 mm, "wheel 200 mm round"
    assert len(wheel.scale.tick) == 50, "50 ticks"
    assert wheel.scale.tick[10].length == 5 mm and wheel.scale.tick[5].length == 3 mm and
        wheel.scale.tick[1].length == 1.5 mm, "tick lengths"
    assert len(wheel.scale.km) == 5, "km 0-4"
    assert distance(wheel.scale.km, wheel.scale.tick) >= 0.5 mm, "numbers clear of the ticks"
    assert distance(wheel.scale.km50, wheel.scale.km) >= 0.5 mm, "number rings apart"
    assert cheek[0].lanyard.c.center.y - cheek[0].axle.c.center.y == -110 mm, "grip 110 mm"
    assert cheek[0].grip_shape.bb.width == 22 mm, "22 mm at the end"
    assert cheek[0].pointer.points[2].y == 27 mm, "pointer to 27 mm"
    assert R - 27 mm >= 4 mm, "the pointer stays inside the rim"
    assert spacer.body.bb.top == -42 mm and R + 5 mm <= 42 mm, "spacer clear of the wheel"
    assert distance(cheek[0].legend, cheek[0].lanyard) >= 3 mm, "legend clear of the lanyard"
    assert cheek[0].legend.bb.left - cheek[0].grip_shape.bb.left >= 2 mm, "legend on the grip"
}
