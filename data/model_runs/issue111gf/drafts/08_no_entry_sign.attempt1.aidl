# Request (signs): a workshop door sign in the style of the "No entry" road sign, layered 3 mm
# acrylic, four parts. A grey backing 220 x 290 mm (R12) screwed to the door by four M4
# countersunk screws 12 mm in from the corners (heads 9 mm). A red disc 200 mm across glued on
# it, its centre 35 mm above the backing's centre. A white bar 160 x 40 mm glued across the
# disc's centre. Under the disc a white plate 180 x 44 mm (R4), centred 100 mm below the
# backing's centre, with "NO ENTRY" cut through it as bold stencil letters 24 mm tall, so the
# grey backing shows through as the letters. The outlines of the disc and the plate are
# engraved on the backing as glue guides.

units mm
thickness 3 mm

import "std/fasteners.aidl"

t = 3
disc_c = (0, 35)
plate_c = (0, -100)

assembly no_entry {
    solid backing {
        body = RoundedRectangle(center=(0, 0), width=220, height=290, corner_radius=12)
        Fixed(body)
        screw = clearance_hole(size=4)
        screws = CornerPattern(screw, body, inset=12)
        Countersink(screws, diameter=9)
        drawing guides {
            disc_guide = Circle(center=disc_c, diameter=200)
            plate_guide = RoundedRectangle(center=plate_c, width=180, height=44, corner_radius=4)
        }
    }

    solid disc {
        c = Circle(center=disc_c, diameter=200)
    }

    solid bar {
        r = Rectangle(center=disc_c, width=160, height=40)
    }

    solid plate {
        body = RoundedRectangle(center=plate_c, width=180, height=44, corner_radius=4)
        hole letters {
            word = Text("NO ENTRY", position=plate_c, size=24, font="sans:Bold", valign="middle",
                        stencil=true)
        }
    }

    # flat layout: the parts side by side for cutting
    RightOf(disc, backing, gap=10)
    AlignTop(disc, backing)
    Below(bar, disc, gap=10)
    AlignLeft(bar, disc)
    Below(plate, bar, gap=10)
    AlignLeft(plate, disc)

    # 3D: all drawn in the backing's frame, stacked up
    Place(backing, position=(0, 0, 0))
    Place(disc, position=(0, 0, t))
    Place(bar, position=(0, 0, 2 * t))
    Place(plate, position=(0, 0, t))

    assert backing.body.bb.width == 220 mm and backing.body.bb.height == 290 mm, "backing"
    assert len(backing.screws) == 4, "four screws"
    assert backing.screws[0].c.center.x - backing.body.bb.left == 12 mm and
        backing.screws[0].c.center.y - backing.body.bb.bottom == 12 mm, "12 mm in"
    assert disc.c.diameter == 200 mm, "disc 200"
    assert disc_c[1] - 0 mm == 35 mm, "disc 35 above the centre"
    assert bar.r.bb.width == 160 mm and bar.r.bb.height == 40 mm, "bar 160 x 40"
    assert plate.body.bb.width == 180 mm and plate.body.bb.height == 44 mm, "plate 180 x 44"
    assert plate_c[1] == -100 mm, "plate 100 below the centre"
    assert (disc_c[1] - 100 mm) - (plate_c[1] + 22 mm) >= 10 mm, "plate clear of the disc"
    assert disc_c[1] + 100 mm <= 145 mm and 100 mm <= 110 mm, "disc on the backing"
    assert plate.letters.word.bb.width <= 180 mm - 2 * 10 mm, "10 mm margin either side"
    assert plate.letters.word.bb.height <= 44 mm - 2 * 6 mm, "6 mm margin above and below"
    # screws clear of the disc (corner screw to the disc's centre, as drawn in the backing)
    assert distance(backing.screws[2].c.center, backing.body.center + disc_c) >= 100 mm + 9 mm,
        "screw heads clear of the disc"
}
