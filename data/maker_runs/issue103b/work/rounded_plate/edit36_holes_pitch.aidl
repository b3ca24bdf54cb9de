# imported from rounded_plate.svg by `aidl import --infer`: edit freely
# recognised: 11 of 11 pieces of outlines and holes in 4 shapes (3 Circle, 1 RoundedRectangle)
# patterns: 1 row
# equal within 1e-07 mm, numbers rounded within 1e-09 mm; the rest stays exact Line/Arc chains
units mm
param width = 90 mm
param height = 50 mm
param corner_radius = 8 mm
param holes_d = 6 mm
param holes_pitch = 24 mm
param holes_n = 3
solid plate {
    body = RoundedRectangle(center=(50, -30), width=width, height=height, corner_radius=corner_radius)
    Fixed(body)
    # row: x about its middle
    for i in range(holes_n) {
        hole holes { h = Circle(center=(50 + (i - (holes_n - 1) / 2) * holes_pitch, -30), diameter=holes_d) }
        Fixed(holes.h)
    }
}
