# imported from corner_plate.dxf by `aidl import --infer`: edit freely
# recognised: 8 of 8 pieces of outlines and holes in 5 shapes (4 Circle, 1 Rectangle)
# patterns: 1 corner
# equal within 1e-07 mm, numbers rounded within 1e-09 mm; the rest stays exact Line/Arc chains
# a 4.4 mm hole at (90, 50) completes a pattern of 4 mm holes: one pattern, that hole its own size (`_odd_d`)
units mm
param width = 100 mm
param height = 60 mm
param corner_hole_d = 4 mm
param corner_inset = 8 mm  # from the edges
param corner_holes_odd_d = 4.4 mm
solid plate {
    body = Rectangle(center=(width / 2, height / 2), width=width, height=height)
    Fixed(body)
    # at the corners, corner_inset in from the edges
    for sx in [-1, 1] {
        for sy in [-1, 1] {
            hole corner_holes { h = Circle(center=(width / 2 + sx * (width / 2 - corner_inset), height / 2 + sy * (height / 2 - corner_inset)), diameter=(corner_holes_odd_d if sx == 1 and sy == 1 else corner_hole_d)) }
            Fixed(corner_holes.h)
        }
    }
}
