# Request: a front-wheel riser block for my turbo trainer (700c wheel, 340 mm radius with the
# tyre), glued up from eight layers of 6 mm birch ply: 48 mm tall. Every layer is 320 x 120 mm
# with 20 mm corner radii and four 6 mm dowel holes at (+-140, +-40) from its centre to line
# the layers up. The top three layers hold the tyre in a stepped cradle: a 32 mm wide
# slot along the length, centred, 220 mm long in the top layer, 180 mm in the second and
# 130 mm in the third, so the tyre (bottom resting on the fourth layer from the top, 18 mm
# down) clears every step. "700C" engraved 10 mm tall at both ends of the top layer, reading
# along the block.

t = 6 mm
thickness t
layers = 8
wheel_r = 340 mm
# slot length per layer, from the bottom layer (0) up; 0: no slot
slot_len = [0 mm, 0 mm, 0 mm, 0 mm, 0 mm, 130 mm, 180 mm, 220 mm]

def riser_layer(slot=0 mm, top=false) -> solid {
    body = RoundedRectangle(center=(0, 0), width=320 mm, height=120 mm, corner_radius=20 mm)
    hole dowels {
        a = Circle(center=(-140 mm, -40 mm), diameter=6 mm)
        b = Circle(center=(140 mm, -40 mm), diameter=6 mm)
        c = Circle(center=(-140 mm, 40 mm), diameter=6 mm)
        d = Circle(center=(140 mm, 40 mm), diameter=6 mm)
    }
    if slot > 0 mm {
        hole cradle { s = Slot(center=(0, 0), length=slot, width=32 mm) }
    }
    if top {
        drawing mark {
            l = Text("700C", position=(-135 mm, 0), size=10, valign="middle", rotation=90 deg)
            r = Text("700C", position=(135 mm, 0), size=10, valign="middle", rotation=-90 deg)
        }
    }
}

assembly riser {
    for k in range(layers) {
        layer = riser_layer(slot=slot_len[k], top=(k == layers - 1))
    }
    # flat: two columns
    for k in range(1, layers) {
        if k % 2 == 1 {
            RightOf(layer[k], layer[k - 1], gap=6)
            AlignBottom(layer[k], layer[k - 1])
        } else {
            Above(layer[k], layer[k - 2], gap=6)
            AlignLeft(layer[k], layer[k - 2])
        }
    }
    # glued stack
    for k in range(layers) {
        Place(layer[k], position=(0, 0, k * t), face="up")
    }

    assert layers * t == 48 mm, "48 mm tall"
    assert layer[0].body.width == 320 mm and layer[0].body.height == 120 mm, "320 x 120 layers"
    assert layer[7].cradle.s.length == 220 mm, "top slot 220"
    assert layer[6].cradle.s.length == 180 mm, "second slot 180"
    assert layer[5].cradle.s.length == 130 mm, "third slot 130"
    assert layer[7].cradle.s.width == 32 mm, "32 mm wide"
    # the tyre sits 18 mm down: each slot clears the wheel's chord at the layer's top face
    for j in range(3) {
        assert layer[5 + j].cradle.s.length >= 2 * sqrt(2 * wheel_r * (j + 1) * t - ((j + 1) * t) ** 2), "the tyre clears the step"
    }
    assert distance(layer[0].dowels.a.center, layer[0].dowels.d.center) == sqrt(280 ** 2 + 80 ** 2) * 1 mm, "dowels at +-140, +-40"
    assert layer[7].mark.l.size == 10 mm, "700C 10 mm tall"
    assert distance(layer[7].mark, layer[7].cradle) >= 3 mm, "the engraving clear of the cradle"
}
