# Ruler: a 200 mm scale on a 220 x 35 mm plate (3 mm corner radius): ticks
# along the top edge, 4 mm every millimetre, 6 mm every 5 mm and 9 mm every
# centimetre; numbers 0 to 20 (4 mm high) under the centimetre ticks; "mm" engraved
# at the right; a 6 mm hanging hole at the right end.

param zero = -100 mm   # x of the scale's 0, 10 mm in from the left end

solid ruler {
    plate = RoundedRectangle(center=(0, 0), width=220, height=35, corner_radius=3)
    hole hang { c = Circle(center=(104, -8), diameter=6) }
    drawing scale {
        for i in range(201) {
            t = Line((zero + i, 17.5), (zero + i, 17.5 - (9 if i % 10 == 0 else (6 if i % 5 == 0 else 4))))
        }
        for k in range(21) {
            n = Text(str(k), (zero + 10 * k, 17.5 - 10), size=4, valign="top")
        }
        unit = Text("mm", (zero + 195, -12), size=4, anchor="end")
    }
}
