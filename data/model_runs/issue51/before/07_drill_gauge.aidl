# Drill-bit gauge plate: 120 x 40 mm, nine holes (2..10 mm) in one row,
# each labelled with its size engraved below it.

param plate_w = 120 mm
param plate_h = 40 mm
param pitch = 12.5 mm

solid gauge {
    body = RoundedRectangle(center=(0, 0), width=plate_w, height=plate_h, corner_radius=3)

    hole bores {
        for i in range(9) {
            b = Circle(center=((i - 4) * pitch, 5), diameter=(i + 2) * 1 mm)
        }
    }

    drawing labels {
        for i in range(9) {
            t = Text(str(i + 2), position=((i - 4) * pitch, -10), size=5, valign="middle")
        }
    }

    Fixed(body)
}
