# imported from hex_vent.dxf by `aidl import --infer`: edit freely
# recognised: 39 of 39 pieces of outlines and holes in 36 shapes (35 Circle, 1 Rectangle)
# patterns: 1 hex grid in a round field, 1 corner
# equal within 1e-07 mm, numbers rounded within 1e-09 mm; the rest stays exact Line/Arc chains
units mm
param width = 100 mm
param height = 70 mm
param holes_d = 6 mm
param holes_pitch = 8 mm
param holes_field_d = 56 mm  # the round field the holes lie whole in
param corner_hole_d = 3.5 mm
param corner_inset = 6 mm  # from the edges
solid plate {
    body = Rectangle(center=(width / 2, height / 2), width=width, height=height)
    Fixed(body)
    holes_k = floor(norm((holes_field_d, 0)) / norm((holes_pitch, 0))) + 1     # nodes each way from the centre
    for j in range(-holes_k, holes_k + 1) {
        for i in range(-holes_k, holes_k + 1) {
            if norm(((i + j % 2 / 2) * holes_pitch, j * holes_pitch * sqrt(3) / 2)) + holes_d / 2 <= holes_field_d / 2 + 1e-7 mm {
                hole holes { h = Circle(center=(width / 2 + (i + j % 2 / 2) * holes_pitch, height / 2 + j * holes_pitch * sqrt(3) / 2), diameter=holes_d) }
                Fixed(holes.h)
            }
        }
    }
    # at the corners, corner_inset in from the edges
    hole corner_holes { h = Circle(center=(corner_inset, corner_inset), diameter=corner_hole_d) }
    CornerPattern(corner_holes, body, inset=corner_inset)
}
