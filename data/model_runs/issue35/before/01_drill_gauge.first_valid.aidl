# A drill-bit gauge: a 120 x 40 mm plate with ten holes for 1..10 mm bits in a
# row, each labelled with its size engraved below it.

param width = 120 mm
param height = 40 mm
param count = 10
pitch = 11 mm

solid gauge {
    plate = RoundedRectangle(center=(0, 0), width=width, height=height, corner_radius=3)

    hole bits {
        for i in range(count) {
            h = Circle(center=(-(count - 1) * pitch / 2 + i * pitch, 5), diameter=(i + 1) * 1 mm)
        }
    }

    drawing labels {
        for i in range(count) {
            t = Text(str(i + 1), (-(count - 1) * pitch / 2 + i * pitch, -12), size=5)
        }
    }

    AlignCenterX(bits, plate)
    AlignCenterX(labels, plate)
    Below(labels, bits, gap=4)
}
