# Request (toys): a crocodile shadow puppet for the kids' puppet theatre, cut from 2 mm
# black polypropylene.
# - The body is a smooth crocodile silhouette 312 mm from snout tip to tail tip (snout at
#   the right), with a front and a back leg, six pointed teeth (5 mm wide, 6 mm long)
#   hanging from the upper jaw every 8 mm from 104 mm right of centre, a 7 mm eye hole,
#   and a row of eight 5 mm "scale" holes 20 mm apart along the body that let the light
#   through.
# - The lower jaw is a separate piece on a 3 mm split pin (3.2 mm holes in both parts) so
#   the mouth opens; it has five teeth pointing up between the upper ones and a lever
#   stub that sticks out under the head with a 2.5 mm hole for its control rod.
# - The body's main rod hole (4 mm) sits at its middle, under the row of scale holes.
# - Shown: the jaw laid on the body, pivot holes lined up.

thickness 2 mm

pivot = (86, 2)

assembly puppet {
    solid body {
        outline = Spline([(152, 6), (130, 15), (104, 27), (88, 24), (60, 22), (20, 32),
                          (-30, 30), (-80, 20), (-125, 10), (-160, 2), (-125, 0),
                          (-80, -6), (-30, -14), (20, -16), (60, -14), (80, -10),
                          (95, -2), (120, 0)], closed=true, corners=[0, 9])
        front_leg = Polygon([(30, -12), (48, -12), (54, -32), (38, -32)])
        back_leg = Polygon([(-62, -8), (-44, -8), (-38, -28), (-54, -28)])
        for i in range(6) {
            tooth = Triangle(center=(104 + 8 * i, [-1.3, -0.6, 0, 1.5, 3, 4.5][i] - 1),
                             base=5, height=6, rotation=180 deg)
        }
        hole eye { c = Circle(center=(104, 18), diameter=7) }
        hole pin { c = Circle(center=pivot, diameter=3.2) }
        hole rod { c = Circle(center=(0, -6), diameter=4) }
        hole scale { c = Circle(center=(-90, 10), diameter=5) }
        scales = LinearPattern(scale, 8, (20, 0))
        Fixed(outline)
    }

    solid jaw {
        hinge = Circle(center=pivot, radius=7)
        tip = Circle(center=(146, -2), radius=3)
        lever = Circle(center=(74, -16), radius=5)
        shape = Hull(hinge, tip, lever)
        for i in range(5) {
            fang = Triangle(center=(108 + 8 * i, 8 - (108 + 8 * i - 86) / 62 * 1 + 1),
                            base=5, height=6)
        }
        hole pin { c = Circle(center=pivot, diameter=3.2) }
        hole rod { c = Circle(center=(74, -16), diameter=2.5) }
        Fixed(hinge)
    }

    # flat on the sheet: the jaw beside the body
    Below(jaw, body, gap=5)
    # assembled: the jaw lies on the body, pin holes on one axis
    Place(body, position=(0, 0, 0))
    Place(jaw, position=(0, 0, 2))

    assert body.outline.points[0].x - body.outline.points[9].x == 312 mm, "snout to tail"
    assert len(body.tooth) == 6 and len(jaw.fang) == 5
    assert len(body.scales) == 8
    assert body.scales[1].c.center.x - body.scales[0].c.center.x == 20 mm
    assert body.eye.c.diameter == 7 mm and body.rod.c.diameter == 4 mm
    assert body.pin.c.diameter == 3.2 mm and jaw.pin.c.diameter == 3.2 mm
    assert jaw.rod.c.diameter == 2.5 mm
    # as written (Place'd parts are read where they are written): the pins line up
    assert body.pin.c.center.x == jaw.pin.c.center.x and body.pin.c.center.y == jaw.pin.c.center.y
    assert body.tooth[1].center.x - body.tooth[0].center.x == 8 mm
}
