# Wine-glass charms for a party, six of them, 3 mm acrylic: each a 34 mm disc with a
# 10 mm hole for the glass stem, its centre 9 mm above the disc's centre, and a 6 mm wide
# throat from that hole out through the top edge (the stem slips in, the charm hangs).
# Each charm carries its number 1 to 6 engraved filled, sans Bold, 12 mm cap height,
# centred left to right, its middle 7 mm below the disc's centre. On the sheet: the six
# in a row, 4 mm apart.

units mm
thickness 3 mm

param count = 6, min = 2, max = 12
param stem_d = 10 mm, min = 8 mm, max = 14 mm
param throat = 6 mm, min = 4 mm, max = 8 mm

def charm(n=1) -> solid {
    disc = Circle(center=(0, 0), diameter=34)
    hole stem {
        eye = Circle(center=(0, 9), diameter=stem_d)
        mouth = Rectangle(center=(0, 15), width=throat, height=12)
    }
    drawing number {
        digit = Text(str(n), position=(0, -7), size=12, valign="middle",
                     font="sans:Bold", fill=true)
    }
}

assembly charms {
    for i in range(count) {
        c = charm(n=i + 1)
    }
    for i in range(1, count) {
        RightOf(c[i], c[i - 1], gap=4)
        AlignBottom(c[i], c[0])
    }

    assert len(c) == 6, "six charms"
    assert c[0].disc.diameter == 34 mm, "34 mm discs"
    assert c[0].stem.eye.diameter == 10 mm, "10 mm stem hole"
    assert c[0].stem.eye.center.y - c[0].disc.center.y == 9 mm, "stem hole 9 mm above centre"
    assert c[0].stem.mouth.width == 6 mm, "6 mm throat"
    assert c[0].stem.mouth.bb.top > c[0].disc.bb.top, "throat opens through the top edge"
    assert c[0].stem.mouth.bb.bottom <= c[0].stem.eye.center.y, "throat reaches the hole"
    assert c[5].number.digit.size == 12 mm, "12 mm numbers"
    assert abs(c[2].number.bb.center_x - c[2].disc.center.x) < 0.01 mm, "number centred"
    assert c[0].disc.center.y - c[0].number.digit.position.y == 7 mm, "number 7 mm below centre"
    assert c[1].disc.bb.left - c[0].disc.bb.right == 4 mm, "4 mm apart"
    assert c[5].disc.bb.left - c[4].disc.bb.right == 4 mm, "4 mm apart at the end"
    assert abs(c[5].disc.center.y - c[0].disc.center.y) < 0.01 mm, "in a row"
}
