# Coin tray top layer: 150 x 50 mm plate, corner radius 5, with 5 round pockets in a
# row for coins of 16.25, 18.75, 21.25, 23.25 and 25.75 mm (cut 0.5 mm oversize),
# 6 mm web between neighbours, the row centred on the plate.
dias = [16.25, 18.75, 21.25, 23.25, 25.75]
solid tray {
    body = RoundedRectangle(center=(0, 0), width=150, height=50, corner_radius=5)
    hole pockets {
        for i in range(5) {
            p = Circle(center=(-60 + i * 28, 0), diameter=dias[i] + 0.5)
        }
    }
    for i in range(4) {
        Gap(pockets.p[i], pockets.p[i + 1], 6)
    }
    for i in range(5) {
        AlignCenterY(pockets.p[i], body)
    }
    CenterInside(pockets, body)
}
