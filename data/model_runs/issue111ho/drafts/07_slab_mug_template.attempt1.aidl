# Request (crafts): templates for hand-building a tapered slab mug from clay, cut from
# 3 mm clear acrylic. The mug is 90 mm tall, 80 mm across at the rim and 70 mm at the
# foot, so the wall template is the unrolled cone band: its long (outer) arc is the rim,
# 80 x pi long, its short arc the foot, 70 x pi long, its ends 90 mm slant apart... the
# band is as wide as the mug's slant height. Seven 2 mm pin holes along the band's middle
# arc, evenly spread with an eighth of the band left at each end, to prick marks for
# stamped decoration; "SLAB MUG H90 RIM 80 FOOT 70" engraved 6 mm tall along the arc,
# 25 mm inside the middle. A 70 mm base disc with a 2 mm centre pin hole and "BASE 70"
# engraved; a handle strip 110 x 20 mm with round ends and "HANDLE" engraved.

units mm
thickness 3 mm

h = 90 mm
rim_d = 80 mm
foot_d = 70 mm
slant = sqrt(h ** 2 + ((rim_d - foot_d) / 2) ** 2)
r_out = slant * (rim_d / 2) / ((rim_d - foot_d) / 2)
r_in = r_out - slant
r_mid = (r_out + r_in) / 2
sweep = rim_d / r_out * 180 deg
a0 = 90 deg - sweep / 2

assembly mug_kit {
    solid wall {
        apex = Point(0, -r_mid, construction=true)
        band = Sector(center=(0, -r_mid), radius=r_out, start_angle=a0, end_angle=a0 + sweep,
                      inner_radius=r_in)
        hole pin {
            c = Circle(center=(r_mid * cos(a0 + sweep / 8), -r_mid + r_mid * sin(a0 + sweep / 8)),
                       diameter=2)
        }
        pins = CircularPattern(pin, 7, apex, angle=sweep * 3 / 4)
        drawing label {
            ring = Circle(center=(0, -r_mid), radius=r_mid - 25, construction=true)
            t = Text("SLAB MUG H90 RIM 80 FOOT 70", along=ring, size=6)
        }
    }
    solid base {
        disc = Circle(center=(0, 0), diameter=70)
        hole centre {
            c = Circle(center=(0, 0), diameter=2)
        }
        drawing label {
            t = Text("BASE 70", (0, -12), size=6)
        }
    }
    solid handle {
        strip = Slot(center=(0, 0), length=110, width=20)
        drawing label {
            t = Text("HANDLE", (0, 0), size=6, valign="middle")
        }
    }

    Below(base, wall, gap=10)
    AlignLeft(base, wall)
    RightOf(handle, base, gap=10)
    AlignCenterY(handle, base)

    assert abs(r_out * radians(sweep) - pi * 80 mm) < 0.01 mm, "outer arc is the rim, 80 x pi"
    assert abs(r_in * radians(sweep) - pi * 70 mm) < 0.01 mm, "inner arc is the foot, 70 x pi"
    assert abs(wall.band.width - sqrt(90 ** 2 + 5 ** 2)) < 0.01 mm, "band as wide as the slant"
    assert len(wall.pins) == 7, "seven pin holes"
    assert distance(wall.label, wall.pins) >= 3 mm, "label clear of the pins"
    assert distance(wall.label, wall.apex) > r_in - r_mid + 25 mm, "label inside the band"
    assert base.disc.diameter == 70 mm, "70 mm base"
    assert handle.strip.length == 110 mm and handle.strip.width == 20 mm, "handle 110 x 20"
}
