# Request (gifts): a "best friends" heart pendant that breaks into two, cut from 3 mm
# pink acrylic: a heart 42 mm wide (lobes of 11 mm radius, their centres 20 mm apart and
# 6 mm above the middle) with its point 20 mm below the middle, split top to bottom by one
# zigzag cut (teeth 3 mm either side of the centre line, about 6 mm apart) so the halves
# key into each other and only match each other. A 2.5 mm jump-ring hole in each lobe,
# 11 mm up and 12 mm out from the middle. Engraved: "BE" over "FRI" on the left half,
# "ST" over "ENDS" on the right (5 mm and 3.5 mm letters).

units mm
thickness 3 mm

solid heart {
    left_lobe = Hull(Circle(center=(-10, 6), radius=11), Point(0, -20))
    right_lobe = Hull(Circle(center=(10, 6), radius=11), Point(0, -20))

    cut split {
        z = Polyline([(0, 16), (0, 11), (3, 5), (-3, -1), (3, -7), (-3, -13), (0, -20),
                      (0, -24)])
    }

    hole left_ring {
        c = Circle(center=(-12, 11), diameter=2.5)
    }
    hole right_ring {
        c = Circle(center=(12, 11), diameter=2.5)
    }

    drawing words {
        be = Text("BE", (-9.5, 2.5), size=5)
        fri = Text("FRI", (-9.5, -4), size=3.5)
        st = Text("ST", (9.5, 2.5), size=5)
        ends = Text("ENDS", (9, -4), size=3.5)
    }

    assert self.bb.width == 42 mm, "42 mm wide"
    assert left_lobe.bb.bottom == -20 mm, "point 20 mm below the middle"
    assert right_ring.c.center.x - left_ring.c.center.x == 24 mm, "rings 12 mm out each side"
    assert distance(words, split) >= 1.5 mm, "words clear of the zigzag"
    assert distance(words, left_ring) >= 1.5 mm and distance(words, right_ring) >= 1.5 mm,
        "words clear of the rings"
}
