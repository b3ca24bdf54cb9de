# Robot chassis: a 150 mm round plate (3 mm) with two 26 x 66 mm wheel cut-outs
# centred 52 mm left and right of the centre; for each TT gear motor two 3.2 mm
# holes 17.5 mm apart, 18 mm inside its wheel cut-out, on the centre line; a
# caster at the back (4 x 3.2 mm holes on a 26 x 26 mm square, 50 mm behind the
# centre); a 30 x 8 mm cable slot 20 mm in front of the centre; four 3.2 mm holes
# for a battery box (58 x 30 mm hole spacing) at the centre.

solid chassis {
    plate = Circle(center=(0, 0), diameter=150)
    hole wheels {
        l = Rectangle(center=(-52, 0), width=26, height=66)
        r = Rectangle(center=(52, 0), width=26, height=66)
    }
    hole motors {
        for s in [-1, 1] {
            a = Circle(center=(s * (52 - 13 - 18), 8.75), diameter=3.2)
            b = Circle(center=(s * (52 - 13 - 18), -8.75), diameter=3.2)
        }
    }
    hole caster {
        for dx in [-13, 13] {
            for dy in [-13, 13] {
                c = Circle(center=(dx, -50 + dy), diameter=3.2)
            }
        }
    }
    hole cables { s = Slot(center=(0, 20), length=30, width=8) }
    hole battery {
        for dx in [-29, 29] {
            for dy in [-15, 15] {
                c = Circle(center=(dx, dy), diameter=3.2)
            }
        }
    }
}
