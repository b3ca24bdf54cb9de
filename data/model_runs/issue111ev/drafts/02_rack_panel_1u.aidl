# Request: a 1U 19-inch rack front panel for my home-built stereo DI / line box, cut from
# 3 mm black acrylic with white-filled engraving.
# - Panel 482.6 x 43.6 mm (1U less 0.85 mm clearance), square corners.
# - Rack ears: four oval slots 10 mm long x 6.5 mm wide (horizontal), centres 465.1 mm
#   apart left to right and 31.75 mm apart top to bottom, centred on the panel.
# - Two Neutrik D-size XLR inputs at x = -140 and -100 mm from the panel centre, on its
#   middle line: a 24 mm hole each plus two 3.2 mm screw holes on the diagonal, 19 mm across
#   and 24 mm up/down (top-left, bottom-right). Labels "L" and "R" engraved 17 mm to the
#   right of each centre.
# - Ten vent slots 25 x 3 mm, vertical, 8 mm pitch, the row centred at x = -4 mm.
# - A 5 mm power LED at x = 70, y = -4, with "ON" engraved 10 mm above it.
# - A 19 x 13 mm rocker switch cut-out at x = 110, with "POWER" engraved under it.
# - An IEC C14 inlet at x = 170: a 27.5 x 20 mm cut-out with its top two corners chamfered
#   4 mm, and two M3 (3.2 mm) screw holes 40 mm apart; "100-240 V~" engraved under it.
# - The title "DI-2" in bold letters, 10 mm tall, filled engraving, starting 20 mm in from
#   the left slot's centre.

thickness 3 mm

panel_w = 482.6 mm
panel_h = 43.6 mm
ear_dx = 465.1 mm
ear_dy = 31.75 mm

def xlr_d(x=0 mm, y=0 mm) -> hole {
    bore = Circle(center=(x, y), diameter=24)
    m1 = Circle(center=(x - 9.5, y + 12), diameter=3.2)
    m2 = Circle(center=(x + 9.5, y - 12), diameter=3.2)
}

solid panel {
    body = Rectangle(center=(0, 0), width=panel_w, height=panel_h)

    hole ear {
        s = Slot(center=(-ear_dx / 2, -ear_dy / 2), length=10, width=6.5)
    }
    ears = CornerPattern(ear, at=[(-ear_dx / 2, -ear_dy / 2), (ear_dx / 2, -ear_dy / 2),
                                  (ear_dx / 2, ear_dy / 2), (-ear_dx / 2, ear_dy / 2)])

    in_l = xlr_d(x=-140 mm, y=0 mm)
    in_r = xlr_d(x=-100 mm, y=0 mm)

    hole vent {
        s = Slot(center=(-4 - 4.5 * 8, 0), length=25, width=3, rotation=90)
    }
    vents = LinearPattern(vent, 10, (8, 0))

    hole led {
        c = Circle(center=(70, -4), diameter=5)
    }
    hole switch {
        r = Rectangle(center=(110, 0), width=19, height=13)
    }
    hole iec {
        r = Polygon([(170 - 13.75, -10), (170 + 13.75, -10), (170 + 13.75, 6), (170 + 9.75, 10),
                     (170 - 9.75, 10), (170 - 13.75, 6)])
        m1 = Circle(center=(150, 0), diameter=3.2)
        m2 = Circle(center=(190, 0), diameter=3.2)
    }

    drawing labels {
        l = Text("L", position=(-140 + 17, 0), size=4, valign="middle")
        r = Text("R", position=(-100 + 17, 0), size=4, valign="middle")
        on = Text("ON", position=(70, 6), size=3.5, valign="middle")
        pw = Text("POWER", position=(110, -15), size=3.5, valign="middle")
        v = Text("100-240 V~", position=(170, -15.5), size=3.5, valign="middle")
    }
    drawing title {
        t = Text("DI-2", position=(-ear_dx / 2 + 20, 0), size=10, anchor="start", valign="middle",
                 font="sans:Bold", fill=true)
    }
    Fixed(body)

    assert body.bb.width == 482.6 mm and body.bb.height == 43.6 mm, "1U panel 482.6 x 43.6"
    assert len(ears) == 4, "four rack slots"
    assert ears[1].s.center.x - ears[0].s.center.x == 465.1 mm, "rack holes 465.1 apart"
    assert ears[3].s.center.y - ears[0].s.center.y == 31.75 mm, "rack holes 31.75 apart"
    assert in_l.bore.diameter == 24 mm, "XLR D-size bore"
    assert in_l.bore.center.x - body.center.x == -140 mm, "L input at -140"
    assert in_r.bore.center.x - body.center.x == -100 mm, "R input at -100"
    assert in_l.m2.center.x - in_l.m1.center.x == 19 mm, "XLR screws 19 across"
    assert in_l.m1.center.y - in_l.m2.center.y == 24 mm, "XLR screws 24 up"
    assert len(vents) == 10, "ten vents"
    assert abs((vents[0].s.center.x + vents[9].s.center.x) / 2 - (-4 mm)) < 0.01 mm, "vent row centred at -4"
    assert iec.m2.center.x - iec.m1.center.x == 40 mm, "IEC screws 40 apart"
    assert iec.r.bb.width == 27.5 mm and iec.r.bb.height == 20 mm, "IEC cut-out 27.5 x 20"
    assert switch.r.bb.width == 19 mm and switch.r.bb.height == 13 mm, "switch 19 x 13"
    assert distance(labels, in_l) >= 1 mm and distance(labels, in_r) >= 1 mm, "labels clear of the XLR holes"
    assert distance(labels, iec) >= 1 mm and distance(labels, switch) >= 1 mm, "labels clear of the cut-outs"
    assert distance(title, ears) >= 2 mm and distance(title, in_l) >= 2 mm, "title clear of the holes"
}
