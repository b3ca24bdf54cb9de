# Request (toys): a gee-haw whimmy-diddle, the folk toy whose propeller spins when you rub
# a stick along a notched one; 4 mm birch ply. The notched stick is 220 x 14 mm, its handle
# end fully rounded (R7), with twelve V-notches along the top edge, 6 mm wide at the edge
# and 4 mm deep, on a 10 mm pitch, the first 20 mm from the tip end; a 2 mm hole for the
# propeller's nail 6 mm from the tip end, on the centre line. "GEE-HAW" engraved on the
# handle. The propeller is 60 x 10 mm with round ends and a 3 mm hole in the middle (it
# spins loose on the 2 mm nail). The rubbing stick is 180 x 10 mm with round ends.

units mm
t = 4 mm
thickness t
kerf 0.1 mm

stick_len = 220 mm
stick_w = 14 mm
notches = 12
notch_w = 6 mm
notch_d = 4 mm
pitch = 10 mm
first_notch = 20 mm
nail_in = 6 mm

assembly whimmy {
    solid stick {
        body = RoundedRectangle(center=(stick_len / 2, 0), width=stick_len, height=stick_w,
                                corner_radii=[stick_w / 2, 0, 0, stick_w / 2])
        # one V-notch, run 1 mm above the edge so it opens cleanly, then the row toward the handle
        hole notch {
            v = Polygon([(stick_len - first_notch - notch_w / 2 * (notch_d + 1) / notch_d, stick_w / 2 + 1),
                         (stick_len - first_notch + notch_w / 2 * (notch_d + 1) / notch_d, stick_w / 2 + 1),
                         (stick_len - first_notch, stick_w / 2 - notch_d)])
        }
        row = LinearPattern(notch, notches, (-pitch, 0))
        hole nail { c = Circle(center=(stick_len - nail_in, 0), diameter=2) }
        drawing name {
            word = Text("GEE-HAW", position=(45, 0), size=6, valign="middle")
        }
    }

    solid prop {
        blade = Slot(center=(0, 0), length=60, width=10)
        hole axle { c = Circle(center=(0, 0), diameter=3) }
    }

    solid rubber {
        rod = Slot(center=(0, 0), length=180, width=10)
    }

    # cutting layout
    Below(prop, stick, gap=6)
    AlignLeft(prop, stick)
    Below(rubber, prop, gap=6)
    AlignLeft(rubber, stick)

    # in 3D: the stick on edge, the propeller on its front face at the nail, the rubbing
    # stick lying on the notched edge
    Place(stick, position=(0, 0, 0), face="front", up="up")
    Place(prop, position=(stick_len - nail_in, -t, 0), face="front", up="up")
    Place(rubber, position=(150, 0, stick_w / 2 + 5), face="front", up="up")

    # the request's numbers
    assert stick.body.width == 220 mm and stick.body.height == 14 mm
    assert len(stick.row) == 12
    assert abs(stick.body.bb.right - stick.row[0].v.points[2].x - 20 mm) < 0.01 mm
    assert abs(stick.row[0].v.points[2].x - stick.row[1].v.points[2].x - 10 mm) < 0.01 mm
    assert abs(stick.body.bb.top - stick.row[0].v.points[2].y - 4 mm) < 0.01 mm
    assert abs(stick.body.bb.right - stick.nail.c.center.x - 6 mm) < 0.01 mm
    assert prop.blade.length == 60 mm and prop.blade.width == 10 mm
    assert prop.axle.c.diameter == 3 mm and stick.nail.c.diameter == 2 mm
    assert rubber.rod.length == 180 mm
    # the last notch stays clear of the engraved name
    assert stick.row[11].bb.left - stick.name.bb.right >= 5 mm
}
