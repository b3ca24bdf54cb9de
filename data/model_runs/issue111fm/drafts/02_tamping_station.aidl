# Request: an espresso tamping station for the worktop, glued up from four layers of 6 mm MDF,
# each 200 x 130 mm with R10 corners. The bottom layer is solid. The three layers above it
# (18 mm deep pockets) have: a 64 mm round pocket for the 58 mm portafilter's basket, its
# centre 45 mm left of the middle and 5 mm above it, with a 30 mm wide channel running from
# it out through the front edge for the handle (the channel meets the pocket with R4 and the
# front edge with R3); a 60 mm round pocket for the tamper, centred 55 mm right and 20 mm up;
# a slot pocket 80 x 14 mm for the WDT tool, centred 55 mm right and 45 mm down. Four 4 mm
# holes for alignment dowels in every layer, 12 mm in from both edges at each corner.
# "ESPRESSO" engraved (filled, 9 mm capitals) on the top layer, behind the portafilter pocket.

t = 6 mm
thickness t

def outline_pins() -> hole {
    for p in [(-88, -53), (88, -53), (-88, 53), (88, 53)] {
        pin = Circle(center=(p[0], p[1]), diameter=4)
    }
}

def layer(label=false) -> solid {
    body = RoundedRectangle(center=(0, 0), width=200, height=130, corner_radius=10)
    hole portafilter {
        cup = Circle(center=(-45, 5), diameter=64)
        chan = Rectangle(center=(-45, -32.5), width=30, height=75)
        Fillet([cup, chan], 4)
    }
    hole tamper {
        cup = Circle(center=(55, 20), diameter=60)
    }
    # FIX after the first valid program: the slot at (55, -45) ran into the front right
    # alignment pin (W0508, real); moved to 45 right and 42 down, 5.9 mm clear of the pin
    hole wdt {
        s = Slot(center=(45, -42), length=80, width=14)
    }
    pins = outline_pins()
    Fillet([body, portafilter.chan], 3)
    if label {
        drawing words {
            w = Text("ESPRESSO", position=(-45, 50), size=9, font="sans:Bold", valign="middle",
                     fill=true)
        }
    }
    Rigid(self)
}

assembly station {
    solid base {
        body = RoundedRectangle(center=(0, 0), width=200, height=130, corner_radius=10)
        pins = outline_pins()
    }
    l1 = layer()
    l2 = layer()
    l3 = layer(label=true)

    # flat on the sheet, two by two
    RightOf(l1, base, gap=10)
    AlignTop(l1, base)
    Below(l2, base, gap=10)
    AlignLeft(l2, base)
    RightOf(l3, l2, gap=10)
    AlignTop(l3, l2)

    # stacked in 3D
    Place(base, position=(0, 0, 0), face="up")
    Place(l1, position=(0, 0, 6), face="up")
    Place(l2, position=(0, 0, 12), face="up")
    Place(l3, position=(0, 0, 18), face="up")

    assert base.body.bb.width == 200 mm and base.body.bb.height == 130 mm, "layers 200 x 130"
    assert l3.portafilter.cup.diameter == 64 mm, "portafilter pocket 64"
    assert l3.tamper.cup.diameter == 60 mm, "tamper pocket 60"
    assert l3.portafilter.chan.width == 30 mm, "handle channel 30 wide"
    assert l3.portafilter.chan.bb.bottom < l3.body.bb.bottom, "channel runs out through the front"
    assert l3.portafilter.cup.center.x - l3.body.center.x == -45 mm, "portafilter 45 left"
    assert l3.tamper.cup.center.x - l3.body.center.x == 55 mm, "tamper 55 right"
    assert l3.tamper.cup.center.y - l3.body.center.y == 20 mm, "tamper 20 up"
    assert l3.wdt.s.center.y - l3.body.center.y == -42 mm, "WDT slot 42 down (FIX)"
    assert distance(l3.wdt, l3.pins) >= 3 mm, "WDT slot clear of the pins (FIX)"
    assert l3.pins.pin[3].center.x - l3.body.bb.left == 188 mm, "pins 12 in from the right edge"
    assert distance(l3.words, l3.portafilter) >= 2 mm, "label clear of the pocket"
}
