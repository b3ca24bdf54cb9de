# imported from cable_comb.svg by `aidl import --infer`: edit freely
# recognised: 34 of 34 pieces of outlines and holes in 3 shapes (2 Circle, 1 Rectangle)
# patterns: 1 notches in a side, 1 mirrored pair
# equal within 1e-07 mm, numbers rounded within 1e-09 mm; the rest stays exact Line/Arc chains
units mm
param width = 150 mm
param height = 40 mm
param notches_n = 7
param notches_width = 8 mm
param notches_depth = 20 mm
param notches_pitch = 16 mm
param holes_d = 5 mm
param holes_inset = 10 mm  # from the edges
solid plate {
    body = Rectangle(center=(80, -25), width=width, height=height)
    Fixed(body)
    for i in range(notches_n) {
        hole notches { h = Rectangle(center=(80 + (i - (notches_n - 1) / 2) * notches_pitch, -25 + (height / 2 - notches_depth / 2)), width=notches_width, height=notches_depth) }
        Fixed(notches.h)
    }
    # mirrored about the centre line
    for s in [-1, 1] {
        hole holes { h = Circle(center=(80 + s * (width / 2 - holes_inset), -25 - height / 2 + 10), diameter=holes_d) }
        Fixed(holes.h)
    }
}
