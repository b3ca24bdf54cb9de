# Drill-bit gauge plate: 120 x 40 mm, nine holes 2..10 mm in one row,
# each hole's size engraved below it.

param plate_w = 120 mm
param plate_h = 40 mm
param pitch = 12.5 mm
param hole_y = 6 mm
param label_y = -10 mm

solid gauge {
    plate = RoundedRectangle(center=(0, 0), width=plate_w, height=plate_h, corner_radius=3)
    Fixed(plate)

    for i in range(9) {
        hole bit {
            c = Circle(center=(-4 * pitch + i * pitch, hole_y), diameter=(i + 2) * 1 mm)
        }
    }

    drawing labels {
        for i in range(9) {
            t = Text(str(i + 2), position=(-4 * pitch + i * pitch, label_y), size=4, valign="middle")
        }
    }
}
