# Speaker grille: 100 mm x 100 mm plate, 6 mm corner radius, four 3.4 mm screw holes
# 7 mm in from each side, and a 7 x 7 grid of 6 mm holes on an 9 mm pitch centred
# on the plate.
param size = 100 mm, min = 80 mm, max = 140 mm
param pitch = 9 mm, min = 8 mm, max = 12 mm

solid grille {
    plate = RoundedRectangle(center=(0, 0), width=size, height=size, corner_radius=6)

    hole screw {
        c = Circle(center=(0, 0), diameter=3.4)
    }
    CornerPattern(screw, plate, inset=7)

    hole perf {
        c = Circle(center=(0, 0), diameter=6)
    }
    grid = GridPattern(perf, 7, 7, pitch)
    # the grid's first hole is 3 pitches left of and below the centre
    At(perf.c.center, plate.center, dx=-3 * pitch, dy=-3 * pitch)
}
