# Front panel for an audio amplifier project box: 160 x 90 mm, 3 mm acrylic, R4 corners.
# A window for a 1602 LCD module, 71 x 24 mm, centered left to right, its center 18 mm above
# the panel's center; four 3.2 mm holes for the module on a 75 x 31 mm rectangle centered on
# the window. Three 7 mm potentiometer holes on a row 22 mm above the bottom edge, 40 mm
# apart, the middle one on the center line, each labelled "VOL", "BASS", "TREBLE" engraved
# 4 mm tall, the label's middle 9 mm below its hole's center. A 5 mm power LED hole 12 mm in
# from the right edge and 22 mm above the bottom edge, "PWR" engraved 3 mm tall 7 mm above it.
# Four 3.5 mm mounting holes 5 mm in from each corner.
units mm
thickness 3 mm

names = ["VOL", "BASS", "TREBLE"]

solid panel {
    body = RoundedRectangle(center=(0, 0), width=160, height=90, corner_radius=4)

    hole lcd {
        win = Rectangle(center=(0, 18), width=71, height=24)
    }
    AlignCenterX(lcd, body)
    VerticalDistance(body.center, lcd.win.center, 18)

    frame = Rectangle(center=(0, 18), width=75, height=31, construction=true)
    Concentric(frame, lcd.win)
    hole mscrew {
        c = Circle(center=(-37.5, 2.5), diameter=3.2)
    }
    mscrews = CornerPattern(mscrew, frame)

    hole pots {
        for i in range(3) {
            p = Circle(center=((i - 1) * 40, -23), diameter=7)
        }
    }
    drawing labels {
        for i in range(3) {
            t = Text(names[i], position=((i - 1) * 40, -32), size=4, valign="middle")
        }
        pwr = Text("PWR", position=(68, -16), size=3, valign="middle")
    }

    hole led {
        c = Circle(center=(68, -23), diameter=5)
    }

    hole corner {
        c = Circle(center=(-75, -40), diameter=3.5)
    }
    corners = CornerPattern(corner, body, inset=5)

    assert body.bb.width == 160 mm and body.bb.height == 90 mm, "panel 160 x 90 mm"
    assert lcd.win.width == 71 mm and lcd.win.height == 24 mm, "LCD window 71 x 24 mm"
    assert lcd.win.center.x == body.center.x, "window centered left to right"
    assert lcd.win.center.y - body.center.y == 18 mm, "window center 18 mm above the panel's"
    assert len(mscrews) == 4, "four module holes"
    assert mscrews[1].c.center.x - mscrews[0].c.center.x == 75 mm or mscrews[1].c.center.y - mscrews[0].c.center.y == 31 mm, "module holes on 75 x 31"
    assert mscrew.bb.center_x == lcd.win.center.x - 37.5 mm, "module holes centered on the window (x)"
    assert mscrew.bb.center_y == lcd.win.center.y - 15.5 mm, "module holes centered on the window (y)"
    assert mscrew.c.diameter == 3.2 mm, "module holes 3.2 mm"
    assert len(pots.p) == 3, "three pots"
    assert pots.p[1].center.x - pots.p[0].center.x == 40 mm, "pots 40 mm apart"
    assert pots.p[1].center.x == body.center.x, "middle pot on the center line"
    assert pots.p[0].center.y - body.bb.bottom == 22 mm, "pots 22 mm above the bottom edge"
    assert pots.p[0].center.y - labels.t[0].center.y == 9 mm, "labels 9 mm below the pots"
    assert body.bb.right - led.c.center.x == 12 mm, "LED 12 mm in from the right edge"
    assert led.c.center.y - body.bb.bottom == 22 mm, "LED 22 mm above the bottom edge"
    assert labels.pwr.center.y - led.c.center.y == 7 mm, "PWR 7 mm above the LED"
    assert corner.c.center.x - body.bb.left == 5 mm and corner.c.center.y - body.bb.bottom == 5 mm, "mounting holes 5 mm in"
}
