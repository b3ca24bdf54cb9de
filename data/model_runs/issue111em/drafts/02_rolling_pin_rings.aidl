# Request: rolling-pin thickness rings for a 45 mm beech rolling pin, cut from 3 mm
# acrylic: a pair of rings for each dough thickness 3, 5, 8 and 10 mm (8 rings). Each ring's
# bore is 45.3 mm (slides onto the pin with 0.3 mm play); its outside diameter is the pin's
# 45 mm plus twice the dough thickness, so the pin rides that high above the worktop. Each
# ring has its dough thickness engraved along the middle of its wall ("5 mm"), letters 60 %
# of the wall's width tall. Laid out in a row, 4 mm apart, for cutting; assembled, one pair
# of each size is shown on the pin's ends.

units mm
thickness 3 mm

pin_d = 45 mm
bore_d = 45.3 mm
dough = [3, 5, 8, 10]
biggest = pin_d + 2 * 10 mm

assembly rings {
    for i in range(8) {
        solid ring {
            t = dough[i // 2]
            # FIX after the first valid program: each ring drawn about its own (0, 0), laid
            # out below by relations (Place puts a part's (0, 0) at position=; drawn at
            # x = i * 69 the rings stood 69 mm apart along the pin, W0518's note)
            rim = Circle(center=(0, 0), diameter=pin_d + 2 * t)
            hole bore {
                c = Circle(center=(0, 0), diameter=bore_d)
            }
            drawing label {
                mid = Circle(center=(0, 0), radius=(pin_d + 2 * t + bore_d) / 4,
                             construction=true)
                word = Text(f"{t} mm", along=mid, size=0.6 * (pin_d + 2 * t - bore_d) / 2,
                            valign="middle")
            }
            Concentric(bore.c, rim)
            Concentric(label.mid, rim)
        }
        # (fix: stacked face to face, 3 mm apart, not 4)
        # on the pin (its axis along x, 45 mm above the worktop centre line):
        # left rings at the left end, right rings at the right end
        Place(ring, position=(-160 - 3 * (i // 2) if i % 2 == 0 else 160 + 3 * (i // 2),
                              0, 22.5), face="left" if i % 2 == 0 else "right")
    }

    for i in range(1, 8) {
        RightOf(ring[i], ring[i - 1], gap=4)
        AlignCenterY(ring[i], ring[0])
    }

    assert len(ring) == 8, "four pairs"
    for i in range(8) {
        assert ring[i].rim.diameter - 45 mm == 2 * [3, 5, 8, 10][i // 2], "outside = pin + 2 x dough"
        assert ring[i].bore.c.diameter == 45.3 mm, "bore 45.3"
    }
    # (the 4 mm layout gap is the RightOf above: an assert reads Placed parts where written)
}
