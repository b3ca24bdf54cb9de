# A hexagonal honeycomb coaster: 100 mm across flats, an 8 mm solid rim, and a
# honeycomb of hexagonal holes 10 mm across flats with 2 mm walls filling the
# middle.
param af = 100 mm
param cell = 10 mm
param wall = 2 mm
pitch = cell + wall

solid coaster {
    body = RegularPolygon(center=(0, 0), across_flats=af, sides=6)
    hole cells {
        for i in range(-4, 5) {
            for j in range(-6, 7) {
                if norm((i * pitch * cos(30 deg), j * pitch + i * pitch / 2)) <= af / 2 - 8 mm - cell / 2 {
                    h = RegularPolygon(center=(i * pitch * cos(30 deg), j * pitch + i * pitch / 2), across_flats=cell, sides=6)
                }
            }
        }
    }
}
