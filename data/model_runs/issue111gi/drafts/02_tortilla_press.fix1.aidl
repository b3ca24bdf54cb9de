# Request: a wooden tortilla press, 6 mm birch ply, glued with 8 mm dowel pins.
# - Base: 210 mm wide (x) x 320 mm deep (y), corners R10, centred on the press's centre.
# - Top plate: a 190 mm disc lying on the base, "HECHO A MANO" engraved along a 80 mm radius.
# - Plate hinge at the back: two ears (flat, standing on edge) glued into 25.2 x 6.2 mortises
#   in the plate at x = +-57 mm, y = 52.5 mm; each ear reaches back to the hinge pin at
#   y = 125 mm, 27 mm above the base's underside, through a vertical slot 8.2 wide and 12.2 long
#   so the plate can rise 4 mm over the dough. Ears 105 x 30 mm above the plate plus the tenon.
# - Four cheeks (40 mm wide, 45 mm tall above the base, a 24 x 6 mm tenon in a base mortise,
#   a 8.2 mm pin hole 21 mm above the base top): one outside each ear at the back (0.5 mm gap)
#   and a pair at the front (y = -125 mm) either side of the lever (0.5 mm gap each side).
# - Lever: a 30 mm wide stadium, 330 mm between its end centres, pivoting on an 8 mm pin at
#   the front; lowered, it lies on the plate's centre and its handle reaches past the base's
#   back edge.

thickness 6 mm

param pin_h = 21 mm    # pin above the base's top face

def cheek() -> solid {
    body = Rectangle(bottom_left=(-20, 0), width=40, height=45)
    tenon = Rectangle(bottom_left=(-12, -6), width=24, height=6)
    hole pin { c = Circle(center=(0, 21), diameter=8.2) }
}

def ear() -> solid {
    # local x runs with the press's y (front to back), local y up from the plate's top face
    body = Rectangle(bottom_left=(35, 0), width=105, height=30)
    tenon = Rectangle(bottom_left=(40, -6), width=25, height=6)
    hole pin { s = Slot(center=(125, 13), length=12.2, width=8.2, rotation=90 deg) }
}

assembly tortilla_press {
    solid base {
        body = RoundedRectangle(center=(0, 0), width=210, height=320, corner_radius=10)
        hole mortises {
            bl = Rectangle(center=(-63.5, 125), width=6.2, height=24.2)
            br = Rectangle(center=(63.5, 125), width=6.2, height=24.2)
            fl = Rectangle(center=(-6.5, -125), width=6.2, height=24.2)
            fr = Rectangle(center=(6.5, -125), width=6.2, height=24.2)
        }
        Fixed(body)
    }

    solid plate {
        disc = Circle(center=(0, 0), diameter=190)
        hole mortises {
            l = Rectangle(center=(-57, 52.5), width=6.2, height=25.2)
            r = Rectangle(center=(57, 52.5), width=6.2, height=25.2)
        }
        drawing words {
            ring = Circle(center=(0, 0), radius=80, construction=true)
            # FIX after the first valid program: the words ran across the ears' mortises
            # (W0505); they go under the centre now, read the right way up
            t = Text("HECHO A MANO", along=ring, size=10, flip=true)
        }
        Fixed(disc)
    }

    ear_l = ear()
    ear_r = ear()
    cheek_bl = cheek()
    cheek_br = cheek()
    cheek_fl = cheek()
    cheek_fr = cheek()

    solid lever {
        bar = Slot(start=(0, 0), end=(330, 0), radius=15)
        hole pin { c = Circle(center=(0, 0), diameter=8.2) }
        drawing word { t = Text("PRESS", position=(280, 0), size=8, valign="middle") }
    }

    # flat on the sheet
    RightOf(plate, base, gap=10)
    AlignTop(plate, base)
    Below(lever, base, gap=10)
    AlignLeft(lever, base)
    Below(cheek_bl, lever, gap=10)
    AlignLeft(cheek_bl, lever)
    RightOf(cheek_br, cheek_bl, gap=10)
    AlignTop(cheek_br, cheek_bl)
    RightOf(cheek_fl, cheek_br, gap=10)
    AlignTop(cheek_fl, cheek_br)
    RightOf(cheek_fr, cheek_fl, gap=10)
    AlignTop(cheek_fr, cheek_fl)
    Below(ear_l, plate, gap=10)
    AlignLeft(ear_l, plate)
    Below(ear_r, ear_l, gap=10)
    AlignLeft(ear_r, ear_l)

    # in 3D (z up, y to the back)
    Place(base, position=(0, 0, 0), face="up")
    Place(plate, position=(0, 0, 6), face="up")
    Place(ear_r, position=(54, 0, 12), face="right", up="up")
    Place(ear_l, position=(-60, 0, 12), face="right", up="up")
    Place(cheek_br, position=(60.5, 125, 6), face="right", up="up")
    Place(cheek_bl, position=(-66.5, 125, 6), face="right", up="up")
    Place(cheek_fr, position=(3.5, -125, 6), face="right", up="up")
    Place(cheek_fl, position=(-9.5, -125, 6), face="right", up="up")
    Place(lever, position=(-3, -125, 27), face="right", up="up")

    assert base.body.bb.width == 210 mm and base.body.bb.height == 320 mm, "base 210 x 320"
    assert plate.disc.diameter == 190 mm, "plate 190"
    assert cheek_bl.pin.c.center.y - cheek_bl.body.bb.bottom == 21 mm, "pin 21 above base top"
    assert cheek_bl.body.bb.height == 45 mm and cheek_bl.body.bb.width == 40 mm, "cheek 40 x 45"
    # the lever's pin is 27 above the base's underside: 6 + 21
    assert 6 mm + pin_h == 27 mm, "pins line up"
    # the ear's slot lets the plate rise 4 mm: slot length minus the pin
    assert ear_l.pin.s.length - 8.2 mm >= 4 mm, "plate rises 4 mm"
    # lowered, the lever's underside (27 - 15) lies on the plate's top (6 + 6)
    assert 27 mm - lever.bar.radius == 12 mm, "lever rests on the plate"
    # its handle reaches past the base's back edge (y = 160)
    assert -125 mm + lever.bar.bb.width - 15 mm > 160 mm, "handle past the base"
}
