# Cable comb: a 110 x 40 mm plate with eight 6 mm round cable holes at 12 mm
# pitch, 14 mm below the top edge, each reached by a 3 mm entry slit from the top
# edge; two 4 mm mounting holes 8 mm from the ends, 10 mm above the bottom.

param pitch = 12 mm

solid comb {
    plate = RoundedRectangle(center=(0, 0), width=110, height=40, corner_radius=4)
    hole cables {
        for i in range(8) {
            c = Circle(center=((i - 3.5) * pitch, 20 - 14), diameter=6)
            slit = Rectangle(center=((i - 3.5) * pitch, 20 - 7), width=3, height=14 + 2)
        }
    }
    hole mount {
        a = Circle(center=(-55 + 8, -20 + 10), diameter=4)
        b = Circle(center=(55 - 8, -20 + 10), diameter=4)
    }
}
