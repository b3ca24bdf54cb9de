# Bench power-supply front panel, 120 x 70 mm, 3 mm acrylic, corners rounded 3 mm.
# A panel voltmeter cut-out 45.5 x 26.5 mm, centred left-right, its top 12 mm below
# the panel's top edge. Two 8 mm banana-jack holes, 19 mm apart (centres), centred
# left-right, 18 mm up from the bottom edge. A 6.2 mm toggle-switch hole 15 mm in from
# the left edge and a 12 mm DC barrel-jack hole 15 mm in from the right edge, both at
# the jacks' height. Four 3.2 mm mounting holes 5 mm in from each corner.
# Engraved labels 4 mm tall, baseline 5 mm above the top of the hole they name:
# "+" over the left jack, "-" over the right jack, "ON" over the switch, "12V IN" over
# the barrel jack.

units mm
thickness 3 mm

solid panel {
    body = RoundedRectangle(center=(0, 0), width=120, height=70, corner_radius=3)

    hole meter {
        r = Rectangle(center=(0, 9.75), width=45.5, height=26.5)
    }
    AlignCenterX(meter, body)
    AlignTop(meter, body)
    meter.bb.top == body.bb.top - 12

    hole jack_pos { c = Circle(center=(-9.5, -17), diameter=8) }
    hole jack_neg { c = Circle(center=(9.5, -17), diameter=8) }
    HorizontalDistance(jack_pos.c.center, jack_neg.c.center, 19)
    jack_pos.c.center.y == body.bb.bottom + 18
    Horizontal(jack_pos.c.center, jack_neg.c.center)
    (jack_pos.c.center.x + jack_neg.c.center.x) / 2 == body.center.x

    hole switch { c = Circle(center=(-45, -17), diameter=6.2) }
    hole barrel { c = Circle(center=(45, -17), diameter=12) }
    switch.c.center.x == body.bb.left + 15
    barrel.c.center.x == body.bb.right - 15
    Horizontal(switch.c.center, jack_pos.c.center)
    Horizontal(barrel.c.center, jack_pos.c.center)

    hole mount { c = Circle(center=(-55, -30), diameter=3.2) }
    mounts = CornerPattern(mount, body, inset=5)

    drawing labels {
        plus = Text("+", (-9.5, -4), size=4)
        minus = Text("-", (9.5, -4), size=4)
        on = Text("ON", (-45, -4), size=4)
        dc = Text("12V IN", (45, -4), size=4)
    }
    AlignCenterX(labels.plus, jack_pos)
    AlignCenterX(labels.minus, jack_neg)
    AlignCenterX(labels.on, switch)
    AlignCenterX(labels.dc, barrel)
    labels.plus.position.y == jack_pos.bb.top + 5
    labels.minus.position.y == jack_neg.bb.top + 5
    labels.on.position.y == switch.bb.top + 5
    labels.dc.position.y == barrel.bb.top + 5

    assert body.bb.width == 120 mm and body.bb.height == 70 mm, "120 x 70 panel"
    assert meter.r.width == 45.5 mm and meter.r.height == 26.5 mm, "meter cut-out 45.5 x 26.5"
    assert body.bb.top - meter.bb.top == 12 mm, "meter 12 mm below the top"
    assert abs(meter.bb.center_x - body.bb.center_x) < 0.01 mm, "meter centred"
    assert jack_neg.c.center.x - jack_pos.c.center.x == 19 mm, "jacks 19 mm apart"
    assert jack_pos.c.diameter == 8 mm, "8 mm jacks"
    assert jack_pos.c.center.y - body.bb.bottom == 18 mm, "jacks 18 mm up"
    assert switch.c.diameter == 6.2 mm and switch.c.center.x - body.bb.left == 15 mm, "switch"
    assert barrel.c.diameter == 12 mm and body.bb.right - barrel.c.center.x == 15 mm, "barrel jack"
    assert len(mounts) == 4, "four mounting holes"
    assert mounts[0].c.center.x - body.bb.left == 5 mm and mounts[0].c.center.y - body.bb.bottom == 5 mm, "5 mm in"
    assert labels.dc.position.y - barrel.bb.top == 5 mm, "labels 5 mm over their holes"
    assert labels.dc.size == 4 mm, "4 mm labels"
}
