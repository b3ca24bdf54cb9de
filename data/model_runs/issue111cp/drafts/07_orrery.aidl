# Request (science): a desk tellurion (Sun-Earth orrery) for a classroom, from 3 mm ply,
# five parts. Module 2 gears: a 36-tooth Sun gear glued fixed on an 8 mm dowel post, a
# 12-tooth idler and a 36-tooth Earth gear riding on an arm that swings round the post;
# because the Earth gear has the Sun gear's teeth, it keeps its axis pointing one way all
# year (the seasons).
# - Base: a 240 mm disc, an 8.2 mm hole for the post at the centre, the 12 month names
#   (6 mm letters) engraved round a 100 mm radius with a tick between each two.
# - Arm: a 24 mm wide bar with round ends, holes at 0 (8.4 mm, on the post), 48 and 96 mm
#   (4.2 mm, M4 axle bolts), a pointer tip reaching 118 mm from the post to read the month.
# - Sun gear (36 t, 8 mm bore) engraved with a 12-point star; idler (12 t, 4.5 mm bore);
#   Earth gear (36 t, 4.5 mm bore) engraved "EARTH" and an arrow for the axis' direction.

import "std/gears.aidl"

units mm
thickness 3 mm
t = 3 mm
m = 2 mm
months = ["JAN", "FEB", "MAR", "APR", "MAY", "JUN", "JUL", "AUG", "SEP", "OCT", "NOV", "DEC"]

assembly tellurion {
    solid base {
        disc = Circle(center=(0, 0), diameter=240)
        hole post { c = Circle(center=(0, 0), diameter=8.2) }
        drawing dial {
            ring = Circle(center=(0, 0), radius=100, construction=true)
            for i in range(12) {
                name = Text(months[i], along=ring, angle=(255 - 30 * i) * 1 deg, size=6)
                tick = Line((96 * cos((90 - 30 * i) * 1 deg), 96 * sin((90 - 30 * i) * 1 deg)),
                            (112 * cos((90 - 30 * i) * 1 deg), 112 * sin((90 - 30 * i) * 1 deg)))
            }
        }
    }

    solid arm {
        bar = Slot(start=(0, 0), end=(96, 0), width=24)
        # FIX after the first valid program: the pointer sat under the Earth gear (r 58..134
        # along the arm), which hid the month it pointed at; it is now on a tail behind the
        # post (under the Sun gear's level), and the months are turned half round to match
        tail = Rectangle(center=(-53, 0), width=106, height=12)
        pointer = Polygon([(-106, -6), (-118, 0), (-106, 6)])
        hole post { c = Circle(center=(0, 0), diameter=8.4) }
        hole axles {
            idler = Circle(center=(48, 0), diameter=4.2)
            earth = Circle(center=(96, 0), diameter=4.2)
        }
    }

    sun = spur_gear(teeth=36, module=m, bore=8 mm, phase=0 deg, mate=12, cx=0 mm, cy=0 mm)
    idler = spur_gear(teeth=12, module=m, bore=4.5 mm, phase=165 deg, mate=36, cx=0 mm, cy=0 mm)
    earth = spur_gear(teeth=36, module=m, bore=4.5 mm, phase=180 deg, mate=12, cx=0 mm, cy=0 mm)

    drawing sun_mark { s = Star(center=(0, 0), points=12, outer_radius=25, inner_radius=14) }
    Concentric(sun_mark.s, sun.hub)
    CutInto(sun_mark, sun)

    drawing earth_mark {
        word = Text("EARTH", position=(0, -14), size=6, valign="middle")
        # FIX after the first valid program: the arrow started at -4 and ran across the bore (W0505)
        arrow = Polyline([(0, 5), (0, 22), (-4, 16), (0, 22), (4, 16)])
    }
    AlignCenterX(earth_mark, earth)
    earth_mark.word.position.y == earth.hub.center.y - 14 mm
    CutInto(earth_mark, earth)

    # on the sheet
    RightOf(sun, base, gap=6)
    AlignTop(sun, base)
    Below(idler, sun, gap=6)
    AlignLeft(idler, sun)
    RightOf(earth, idler, gap=6)
    AlignTop(earth, idler)
    Below(arm, earth, gap=6)
    AlignLeft(arm, idler)

    # assembled: base, the arm on it round the post, the gears on the arm's level above
    Place(base, position=(0, 0, 0))
    Place(arm, position=(0, 0, t))
    Place(sun, position=(0, 0, 2 * t))
    Place(idler, position=(48, 0, 2 * t))
    Place(earth, position=(96, 0, 2 * t))

    assert base.disc.diameter == 240 mm, "240 mm base"
    assert len(base.dial.name) == 12, "12 months"
    assert arm.axles.idler.center.x - arm.post.c.center.x == 48 mm, "idler 48 from the post"
    assert arm.axles.earth.center.x - arm.post.c.center.x == 96 mm, "earth 96 from the post"
    assert m * (sun.teeth + idler.teeth) / 2 == 48 mm, "sun and idler mesh at 48"
    assert m * (idler.teeth + earth.teeth) / 2 == 48 mm, "idler and earth mesh at 48"
    assert earth.teeth == sun.teeth, "the Earth keeps its axis"
    assert arm.post.c.center.x - arm.pointer.points[1].x == 118 mm, "pointer reaches 118"
}
