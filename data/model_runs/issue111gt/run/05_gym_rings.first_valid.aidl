# Request (sport): a pair of gymnastic rings for the pull-up bar in the garage, laminated
# from 9 mm birch ply.
# - Each ring is three layers glued up (27 mm grip), 180 mm inside, 236 mm outside.
# - Four 6 mm dowel holes in every layer on the middle of the band (104 mm radius), at 45,
#   135, 225 and 315 degrees, to line the layers up in the glue-up.
# - On each ring's top layer: "L" or "R" engraved at the top of the band (10 mm letters) and
#   "TOMASZ" along the bottom of the band, 6 mm letters, reading the right way up.

t = 9 mm
thickness t

def ring_layer(side="L", outer=false) -> solid {
    band = Circle(center=(0, 0), diameter=236)
    hole inner { c = Circle(center=(0, 0), diameter=180) }
    hole pins {
        for k in range(4) {
            c = Circle(center=(104 * cos(45 deg + k * 90 deg), 104 * sin(45 deg + k * 90 deg)),
                       diameter=6)
        }
    }
    if outer {
        drawing mark {
            path = Circle(center=(0, 0), radius=104, construction=true)
            who = Text("TOMASZ", along=path, size=6, flip=true, valign="middle")
            hand = Text(side, position=(0, 104), size=10, valign="middle")
        }
    }
}

assembly rings {
    for r in range(2) {
        for k in range(3) {
            layer = ring_layer(side="L" if r == 0 else "R", outer=(k == 2))
            # stacked: ring r at x = 300 r, layer k from z = 9 k
            Place(layer, position=(r * 300 mm, 0, k * t))
        }
    }

    # flat layout for cutting: a column of three layers per ring
    for r in range(2) {
        for k in range(1, 3) {
            Below(layer[r][k], layer[r][k - 1], gap=6 mm)
            AlignLeft(layer[r][k], layer[r][0])
        }
    }
    RightOf(layer[1][0], layer[0][0], gap=6 mm)
    AlignTop(layer[1][0], layer[0][0])

    # the request's numbers
    assert len(layer) == 2 and len(layer[0]) == 3, "two rings of three layers"
    assert 3 * t == 27 mm, "27 mm grip"
    assert layer[0][0].inner.c.diameter == 180 mm and layer[0][0].band.diameter == 236 mm,
        "180 inside, 236 outside"
    assert abs(distance(layer[0][0].pins.c[0].center, layer[0][0].band.center) - 104 mm) < 0.01 mm,
        "dowels on a 104 mm radius"
    assert layer[0][0].pins.c[0].diameter == 6 mm and len(layer[0][0].pins.c) == 4, "four 6 mm dowels"
    assert distance(layer[0][0].pins, layer[0][0].inner) >= 5 mm, "dowel holes clear of the inside"
    assert layer[0][2].mark.hand.text == "L" and layer[1][2].mark.hand.text == "R", "L and R"
    assert distance(layer[0][2].mark.who, layer[0][2].pins) >= 3 mm, "name clear of the dowels"
    assert distance(layer[0][2].mark.who, layer[0][2].inner) >= 1 mm, "name on the band"
    assert distance(layer[0][2].mark.hand, layer[0][2].inner) >= 1 mm, "L on the band"
    assert layer[0][2].mark.who.bb.center_y < layer[0][2].band.center.y, "name at the bottom"
}
