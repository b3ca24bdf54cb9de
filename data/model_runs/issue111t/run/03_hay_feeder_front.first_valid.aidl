# Pets: rabbit hay-feeder front, 4 mm plywood. 200 mm wide, straight sides 110 mm tall, an
# arched top rising to 150 mm at the middle. Seven vertical hay slots 12 mm wide, 80 mm long,
# 24 mm apart (centre to centre), centred, their bottoms 30 mm above the bottom edge. Two 4 mm
# screw holes 80 mm either side of the centre line at 100 mm up, countersunk 8 mm. "HAY"
# engraved 12 mm tall, centred, baseline 8 mm up.
thickness 4 mm

solid front {
    bottom = Line((-100, 0), (100, 0))
    right = Line((100, 0), (100, 110))
    top = Arc(start=(100, 110), through=(0, 150), end=(-100, 110))
    left = Line((-100, 110), (-100, 0))

    hole bars {
        s = Slot(center=(-72, 70), length=80, width=12, rotation=90 deg)
    }
    slots = LinearPattern(bars, 7, (24, 0))

    hole screws {
        a = Circle(center=(-80, 100), diameter=4)
        b = Circle(center=(80, 100), diameter=4)
    }
    Countersink([screws.a, screws.b], diameter=8 mm)

    drawing label {
        w = Text("HAY", (0, 8), size=12)
    }

    assert self.bb.width == 200 mm, "200 wide"
    assert self.bb.height == 150 mm, "150 tall at the middle"
    assert right.length == 110 mm, "sides 110 tall"
    assert len(slots) == 7, "seven hay slots"
    assert slots[1].s.center.x - slots[0].s.center.x == 24 mm, "24 apart"
    assert slots[0].s.bb.bottom - bottom.start.y == 30 mm, "30 above the bottom"
    assert abs(slots[3].s.center.x) < 0.01 mm, "centred"
}
