# Request (science): an entomology pinning block, glued up from laser-cut layers. Three
# 40 x 40 steps whose tops stand 8, 16 and 24 mm above the floor of the pin holes: three 8 mm
# ply layers (120, 80 and 40 long, 40 deep, flush at the back and at the right end) on a
# 3 mm ply base 140 x 66 that stands 10 mm out at the back and the ends and 16 mm at the front.
# Every layer has a 1.2 mm pin hole in each step it lies under, 24 mm from the front edge,
# centred in the step, so a pin goes down to the base. Each step's exposed top is engraved
# with its height ("8", "16", "24", 7 mm strokes) in front of its hole, and the base's front
# margin reads "PINNING BLOCK 8 16 24 MM" (5 mm strokes).

thickness 8 mm

step = 40 mm
rise = 8 mm
base_t = 3 mm

def layer(k=1) -> solid {
    body = Rectangle(bottom_left=(step * (k - 1), 0), width=step * (4 - k), height=step)
    hole pins {
        for j in range(k, 4) { c = Circle(center=(step * j - step / 2, 24), diameter=1.2) }
    }
    drawing mark { t = Text(str(8 * k), position=(step * k - step / 2, 6), size=7) }
    Rigid(self)
}

assembly block {
    solid base {
        thickness 3 mm
        plate = Rectangle(bottom_left=(-10, -16), width=140, height=66)
        drawing name { t = Text("PINNING BLOCK 8 16 24 MM", position=(60, -11), size=5) }
        Rigid(self)
    }
    l1 = layer(k=1)
    l2 = layer(k=2)
    l3 = layer(k=3)

    # on the sheet: apart
    Above(l1, base, gap=8)
    AlignLeft(l1, base)
    RightOf(l2, l1, gap=8)
    AlignBottom(l2, l1)
    RightOf(l3, l2, gap=8)
    AlignBottom(l3, l1)

    # in 3D: stacked on the base
    Place(base, position=(0, 0, 0), face="up")
    Place(l1, position=(0, 0, base_t), face="up")
    Place(l2, position=(0, 0, base_t + rise), face="up")
    Place(l3, position=(0, 0, base_t + 2 * rise), face="up")

    assert l1.body.bb.width == 120 mm and l2.body.bb.width == 80 mm and l3.body.bb.width == 40 mm, "120, 80, 40 long"
    assert l1.body.bb.height == 40 mm, "40 deep"
    assert len(l1.pins.c) == 3 and len(l2.pins.c) == 2 and len(l3.pins.c) == 1, "a hole per step below"
    assert l1.pins.c[0].diameter == 1.2 mm, "1.2 mm pin holes"
    assert l1.pins.c[0].center.y - l1.body.bb.bottom == 24 mm, "holes 24 from the front"
    assert base.plate.bb.width == 140 mm and base.plate.bb.height == 66 mm, "base 140 x 66"
    assert l1.mark.t.text == "8" and l2.mark.t.text == "16" and l3.mark.t.text == "24", "heights"
}
