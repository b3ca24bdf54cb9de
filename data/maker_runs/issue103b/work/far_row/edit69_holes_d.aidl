# imported from far_row.dxf by `aidl import --infer`: edit freely
# recognised: 10 of 10 pieces of outlines and holes in 7 shapes (6 Circle, 1 Rectangle)
# patterns: 1 row
# equal within 1e-07 mm, numbers rounded within 1e-09 mm; the rest stays exact Line/Arc chains
# a 5 mm hole at (130, 20) completes a pattern of 4 mm holes: one pattern, that hole its own size (`_odd_d`)
units mm
param width = 140 mm
param height = 40 mm
param holes_d = 3.5 mm
param holes_pitch = 15 mm
param holes_n = 5
param holes_odd_d = 5 mm
param hole1_d = 8 mm
solid plate {
    body = Rectangle(center=(width / 2, height / 2), width=width, height=height)
    Fixed(body)
    # row: x from its end member
    for i in range(holes_n) {
        hole holes { h = Circle(center=(width - 10 + (i - (holes_n - 1)) * holes_pitch, height / 2), diameter=(holes_odd_d if i == 4 else holes_d)) }
        Fixed(holes.h)
    }
    hole hole1 { h = Circle(center=(15, height / 2), diameter=hole1_d) }
    Fixed(hole1.h)
}
