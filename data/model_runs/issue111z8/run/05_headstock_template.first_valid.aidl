# Music: a 3+3 guitar headstock routing template, 6 mm MDF.
# The headstock: 45 mm wide at the nut line (y = 0), its straight sides widening
# to 84 mm wide 160 mm above the nut, closed by a crowned top: an arc through
# the centre line 190 mm above the nut. Below the nut a 45 x 30 tongue to clamp
# the template on the neck, the nut line engraved across it. Six tuner holes
# 10 mm in diameter, 3 a side, 70, 105 and 140 mm above the nut, each 14 mm in
# (horizontally) from its side edge. A truss-rod access slot 10 mm wide from
# 5 to 35 mm above the nut on the centre line. "3+3 HEADSTOCK" engraved 5 mm
# tall along the centre line, reading bottom to top, centred 100 mm above the nut.

units mm
thickness 6 mm

nut_w = 45 mm
top_w = 84 mm
def side_x(y) = nut_w / 2 + (top_w - nut_w) / 2 * y / 160 mm
tuner_y = [70 mm, 105 mm, 140 mm]

solid template {
    bottom = Line((-nut_w / 2, 0), (nut_w / 2, 0))
    right = Line((nut_w / 2, 0), (top_w / 2, 160))
    crown = Arc(start=(top_w / 2, 160), through=(0, 190), end=(-top_w / 2, 160))
    left = Line((-top_w / 2, 160), (-nut_w / 2, 0))
    tongue = Rectangle(center=(0, -15), width=nut_w, height=30)

    hole tuners {
        for i in range(3) {
            r = Circle(center=(side_x(tuner_y[i]) - 14, tuner_y[i]), diameter=10)
            l = Circle(center=(-side_x(tuner_y[i]) + 14, tuner_y[i]), diameter=10)
        }
    }
    hole truss {
        s = Slot(start=(0, 10), end=(0, 30), width=10)
    }
    drawing marks {
        nut = Line((-nut_w / 2, 0), (nut_w / 2, 0))
        t = Text("3+3 HEADSTOCK", position=(0, 100), size=5, valign="middle", rotation=90 deg)
    }

    assert bottom.length == 45 mm, "45 wide at the nut"
    assert right.end.x - left.start.x == 84 mm, "84 wide 160 above the nut"
    assert right.end.y == 160 mm, "sides end 160 above the nut"
    assert crown.through.y == 190 mm and crown.through.x == 0 mm, "crown 190 above the nut"
    assert tongue.width == 45 mm and tongue.height == 30 mm and tongue.bb.top == 0 mm, "tongue 45 x 30"
    assert len(tuners.r) == 3 and len(tuners.l) == 3, "3 + 3 tuners"
    assert tuners.r[0].diameter == 10 mm, "tuner holes 10"
    assert tuners.r[0].center.y == 70 mm and tuners.r[1].center.y == 105 mm and tuners.r[2].center.y == 140 mm, "tuners at 70 / 105 / 140"
    assert truss.s.width == 10 mm and truss.s.bb.bottom == 5 mm and truss.s.bb.top == 35 mm, "truss slot 10 wide, 5 to 35"
    assert marks.t.position.y == 100 mm, "label centred 100 above the nut"
}
