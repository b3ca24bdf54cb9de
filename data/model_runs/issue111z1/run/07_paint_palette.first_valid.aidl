# Crafts: an artist's hand-held paint palette, 3 mm clear acrylic.
# An oval 260 x 190 mm. Thumb hole: an oval opening 28 x 38 mm (upright), its centre 45 mm in
# from the left end and 20 mm below the middle. Finger notch: a 50 mm round bite out of the
# lower-left edge, centred at (-115, -75) from the palette's centre; the notch's two corners with
# the rim rounded R6. Six engraved paint-well rings 28 mm across, on a 70 mm radius about the
# centre, from 150 deg to 0 deg every 30 deg. The owner's name "ANA" engraved in serif outline
# letters, 10 mm tall, centred at (70, -55).
thickness 3 mm

param wells = 6, min = 3, max = 8

solid palette {
    board = Ellipse(center=(0, 0), rx=130, ry=95)
    hole thumb {
        t = Ellipse(center=(-130 + 45, -20), rx=14, ry=19)
    }
    hole notch {
        n = Circle(center=(-115, -75), diameter=50)
    }
    drawing paint {
        for i in range(wells) {
            w = Circle(center=(70 * cos(150 deg - i * 30 deg), 70 * sin(150 deg - i * 30 deg)),
                       diameter=28)
        }
    }
    drawing owner {
        name = Text("ANA", (70, -55), size=10, font="serif", valign="middle")
    }
    Fillet(6)

    assert board.bb.width == 260 mm and board.bb.height == 190 mm, "260 x 190 oval"
    assert thumb.t.bb.width == 28 mm and thumb.t.bb.height == 38 mm, "28 x 38 thumb hole"
    assert thumb.t.center.x - board.bb.left == 45 mm, "thumb hole 45 mm in"
    assert notch.n.diameter == 50 mm, "50 mm notch"
    assert len(paint.w) == 6, "six wells"
}
