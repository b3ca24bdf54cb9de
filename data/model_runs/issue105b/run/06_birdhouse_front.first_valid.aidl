# Birdhouse front panel, 6 mm plywood: 150 mm wide, side walls 160 mm tall, a
# gable roof line at 45 degrees rising to a peak 75 mm above the walls (235 mm
# overall). A round entrance 32 mm in diameter, its center 115 mm above the bottom
# edge, centered left to right; a perch hole 8 mm in diameter (for a dowel) 25 mm
# below the entrance's bottom edge, also centered.

units mm
thickness 6 mm

param w = 150 mm, min = 120 mm, max = 200 mm
param wall_h = 160 mm, min = 120 mm, max = 220 mm
param entrance = 32 mm, min = 25 mm, max = 45 mm

solid front {
    outline = Polygon([(0, 0), (w, 0), (w, wall_h), (w / 2, wall_h + w / 2), (0, wall_h)])

    hole entry {
        c = Circle(center=(75, 115), diameter=entrance)
    }
    AlignCenterX(entry, outline)
    At(entry.c.center, outline.bb.bottom_left, dx=w / 2, dy=115)

    hole perch {
        c = Circle(center=(75, 70), diameter=8)
    }
    AlignCenterX(perch, entry)
    Below(perch, entry, gap=25 - 4)
}
