# Request (science): a desk armillary sphere (sundial) for latitude 52 deg N, 3 mm plywood.
# - A meridian ring, 200 mm outside, 176 mm inside (12 mm band), standing upright
#   north-south; across it the polar axis, a bar 8 mm wide through the centre, tilted
#   52 deg above the north horizon; a flat foot 40 wide at the bottom (10 mm block)
#   with a 20 x 3 mm tenon into the base.
# - An equator ring of the same size, square to the polar axis, crossing the meridian ring
#   at two points with halving joints (each ring notched 6 mm, 0.2 mm clearance): the
#   equator ring from its outer edge, the meridian ring from its inner edge.
# - The equator ring's top face (toward the north pole) engraved with the hours 6 to 18,
#   3.5 mm, their centres on radius 90.5, 15 deg apart, running clockwise with 12 at the
#   low northern crossing (where the axis's shadow falls at noon), 6 to the west; a tick
#   from radius 95 to 99 at each hour but 12 (the notch is there).
# - A round base 150 mm with a 20.2 x 3.2 mm mortise for the tenon, engraved N and S on
#   the meridian line 60 mm from the centre, and "52° N" (filled sans 8 mm) 40 mm to the
#   south of the centre... on the east-west line: centred 40 mm east of the centre.

import "std/joints.aidl"

thickness 3 mm

lat = 52 deg
r_out = 100 mm
r_in = 88 mm
notch = 6 mm

assembly armillary {
    solid meridian {
        # FIX after the first valid program (W0506): the bore cut the axis bar away too;
        # the band and its bore now are a solid of their own beside the bar
        solid ring {
            band = Circle(center=(0, 0), radius=r_out)
            hole bore { c = Circle(center=(0, 0), radius=r_in) }
        }
        solid axis {
            bar = Rectangle(center=(0, 0), width=2 * r_in + 4, height=8, rotation=lat)
        }
        solid foot {
            block = Rectangle(center=(0, -100), width=40, height=10)
            tenon = Rectangle(center=(0, -106.5), width=20, height=3)
        }
        # notched from the inner edge where the equator ring crosses
        n1 = cross_halving(depth=notch, thickness=3 mm, clearance=0.2 mm,
                           rotation=lat + 180 deg,
                           cx=r_in * cos(lat + 90 deg), cy=r_in * sin(lat + 90 deg))
        n2 = cross_halving(depth=notch, thickness=3 mm, clearance=0.2 mm,
                           rotation=lat + 360 deg,
                           cx=r_in * cos(lat + 270 deg), cy=r_in * sin(lat + 270 deg))
    }

    solid equator {
        band = Circle(center=(0, 0), radius=r_out)
        hole bore { c = Circle(center=(0, 0), radius=r_in) }
        # notched from the outer edge at 90 and 270 deg (the crossings)
        n1 = cross_halving(depth=notch, thickness=3 mm, clearance=0.2 mm, rotation=0 deg,
                           cx=0 mm, cy=r_out)
        n2 = cross_halving(depth=notch, thickness=3 mm, clearance=0.2 mm, rotation=180 deg,
                           cx=0 mm, cy=-r_out)
        drawing hours {
            mid = Circle(center=(0, 0), radius=90.5, construction=true)
            for h in range(6, 19) {
                num = Text(str(h), along=mid, angle=270 deg - (h - 12) * 15 deg, size=3.5,
                           valign="middle")
            }
            for h in range(6, 19) {
                if h != 12 {
                    tick = Line(polar((0, 0), 95, 270 deg - (h - 12) * 15 deg),
                                polar((0, 0), 99, 270 deg - (h - 12) * 15 deg))
                }
            }
        }
    }

    solid base {
        plate = Circle(center=(0, 0), diameter=150)
        hole mortise { m = Rectangle(center=(0, 0), width=3.2, height=20.2) }
        drawing marks {
            n = Text("N", position=(0, 60), size=8, valign="middle")
            s = Text("S", position=(0, -60), size=8, valign="middle")
            l = Text("52° N", position=(40, 0), size=8, font="sans", valign="middle",
                     fill=true)
        }
    }

    # flat on the sheet
    RightOf(equator, meridian, gap=10)
    AlignCenterY(equator, meridian)
    RightOf(base, equator, gap=10)
    AlignCenterY(base, equator)

    # in 3D: x east, y north, z up; the sphere's centre 108 above the table
    Place(base, position=(0, 0, 0), face="up", up="back")
    Place(meridian, position=(-1.5, 0, 108), face="right", up="up")
    Place(equator, position=(0, -1.5 * cos(lat), 108 - 1.5 * sin(lat)),
          face=(0, cos(lat), sin(lat)), up=(0, -sin(lat), cos(lat)))

    assert meridian.ring.band.radius * 2 == 200 mm and meridian.ring.bore.c.radius * 2 == 176 mm,
        "rings 200 outside, 176 inside"
    assert meridian.axis.bar.height == 8 mm, "axis bar 8 wide"
    assert meridian.foot.block.bb.bottom - meridian.foot.tenon.bb.bottom == 3 mm,
        "tenon through the 3 mm base"
    # FIX: this assert compared a number with itself; now the foot's flat is 5 mm below the ring
    assert meridian.ring.band.bb.bottom - meridian.foot.block.bb.bottom == 5 mm,
        "foot flat 5 mm below the ring"
    assert len(equator.hours.num) == 13, "hours 6 to 18"
    assert len(equator.hours.tick) == 12, "a tick at each hour but 12"
    assert base.plate.diameter == 150 mm, "150 mm base"
    assert base.mortise.m.width == 3.2 mm and base.mortise.m.height == 20.2 mm, "mortise"
}
