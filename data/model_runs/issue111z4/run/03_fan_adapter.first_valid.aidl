# Electronics: an adapter plate to mount an 80 mm PC fan on a 120 mm fan opening, 3 mm acrylic.
# Plate 120 x 120 mm, corners R6. Four 4.5 mm holes on the 120 mm fan's 105 mm square pattern,
# countersunk 9 mm (90 deg). A round opening 76 mm across in the middle. Four 3.4 mm holes on
# the 80 mm fan's 71.5 mm square pattern (not countersunk), concentric with the opening.
# Engraved "80 > 120 MM", 3.5 mm tall, centred, baseline 3.5 mm above the bottom edge.

units mm
thickness 3 mm

solid adapter {
    plate = RoundedRectangle(center=(0, 0), width=120, height=120, corner_radius=6)

    hole m4 {
        c = Circle(center=(-52.5, -52.5), diameter=4.5)
    }
    big = CornerPattern(m4, plate, inset=(120 - 105) / 2)
    Countersink(big, diameter=9)

    hole opening {
        c = Circle(center=(0, 0), diameter=76)
    }
    Concentric(opening.c, plate.center)

    small_square = Rectangle(center=(0, 0), width=71.5, height=71.5, construction=true)
    Concentric(small_square.center, opening.c)
    hole m3 {
        c = Circle(center=(-35.75, -35.75), diameter=3.4)
    }
    small = CornerPattern(m3, small_square)

    drawing label {
        t = Text("80 > 120 MM", position=(0, -56.5), size=3.5)
    }
    AlignCenterX(label, plate)
    VerticalDistance(plate.bottom.midpoint, label.t.position, 3.5)

    assert plate.bb.width == 120 mm and plate.bb.height == 120 mm, "plate 120 x 120"
    assert big[1].c.center.x - big[0].c.center.x == 105 mm, "120 fan: 105 mm pattern"
    assert big[3].c.center.y - big[0].c.center.y == 105 mm, "120 fan: 105 mm pattern"
    assert small[1].c.center.x - small[0].c.center.x == 71.5 mm, "80 fan: 71.5 mm pattern"
    assert small[3].c.center.y - small[0].c.center.y == 71.5 mm, "80 fan: 71.5 mm pattern"
    assert opening.c.diameter == 76 mm, "76 mm opening"
    assert len(big) == 4 and len(small) == 4, "four holes each"
}
