# Honeycomb coaster: a 95 mm round coaster with a 6 mm solid rim; inside it a
# honeycomb of hexagonal cells 12 mm across flats with 1.8 mm walls between them.

param af = 12 mm
param wall = 1.8 mm
param pitch = af + wall

solid coaster {
    disc = Circle(center=(0, 0), diameter=95)
    hole cells {
        for r in range(-4, 5) {
            for c in range(-4, 5) {
                x = c * pitch * sqrt(3) / 2
                y = r * pitch + (pitch / 2 if c % 2 != 0 else 0)
                if sqrt(x * x + y * y) + af / sqrt(3) <= 95 / 2 - 6 {
                    h = RegularPolygon(center=(x, y), across_flats=af, sides=6, rotation=30 deg)
                }
            }
        }
    }
}
