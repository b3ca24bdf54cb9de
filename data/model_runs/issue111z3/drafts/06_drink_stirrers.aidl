# Party drink stirrers: a set of 6 cut from 2 mm acrylic, laid side by side 35 mm apart (centre to
# centre) for cutting. Each: a stick 6 mm wide with a round bottom end, 150 mm from its round tip to
# the centre of a 5-point star topper (outer radius 15 mm, inner radius 7 mm, tips rounded R1.5, one
# tip straight up); the stirrer's number (1 to 6) engraved in filled sans Bold 6 mm high in the
# star's centre so guests can tell their glasses apart.

units mm
thickness 2 mm

param count = 6, min = 2, max = 12
param pitch = 35 mm, min = 32, max = 50
param stick_len = 150 mm, min = 100, max = 200

def stirrer(n=1) -> solid {
    stick = Slot(start=(0, 3), end=(0, stick_len), width=6)
    star = Star(center=(0, stick_len), points=5, outer_radius=15, inner_radius=7, tip_radius=1.5)
    drawing number {
        t = Text(str(n), position=(0, stick_len), size=6, font="sans:Bold", valign="middle", fill=true)
    }
}

assembly stirrers {
    for i in range(count) {
        s = stirrer(n=i + 1)
        s.stick.start.x == i * pitch
        s.stick.bb.bottom == 0
    }

    assert len(s) == 6, "six stirrers"
    assert s[1].stick.start.x - s[0].stick.start.x == 35 mm, "35 apart"
    assert s[0].stick.width == 6 mm, "stick 6 wide"
    assert s[0].star.center.y - s[0].stick.bb.bottom == 150 mm, "150 from the tip to the star's centre"
    assert s[0].star.outer_radius == 15 mm and s[0].star.inner_radius == 7 mm, "star R15 / R7"
    assert s[5].n == 6, "numbered 1 to 6"
    assert s[0].number.t.size == 6 mm, "numbers 6 high"
}
