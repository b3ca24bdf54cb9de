# imported from fan_grille.dxf by `aidl import --infer`: edit freely
# recognised: 57 of 57 pieces of outlines and holes in 50 shapes (49 Circle, 1 RoundedRectangle)
# patterns: 1 corner, 1 grid in a round field
# equal within 1e-07 mm, numbers rounded within 1e-09 mm; the rest stays exact Line/Arc chains
units mm
param width = 50 mm
param height = 50 mm
param corner_radius = 3 mm
param corner_hole_d = 4.3 mm
param corner_inset = 5 mm  # from the edges
param holes_d = 3 mm
param holes_pitch = 4.5 mm
param holes_field_d = 40 mm  # the round field the holes lie whole in
solid plate {
    body = RoundedRectangle(center=(0, 0), width=width, height=height, corner_radius=corner_radius)
    Fixed(body)
    # at the corners, corner_inset in from the edges
    hole corner_holes { h = Circle(center=(-width / 2 + corner_inset, -height / 2 + corner_inset), diameter=corner_hole_d) }
    CornerPattern(corner_holes, body, inset=corner_inset)
    # a grid clipped to a round field, about its centre
    holes_k = floor(norm((holes_field_d, 0)) / norm((holes_pitch, 0))) + 1     # nodes each way from the centre
    for j in range(-holes_k, holes_k + 1) {
        for i in range(-holes_k, holes_k + 1) {
            if norm((i * holes_pitch, j * holes_pitch)) + holes_d / 2 <= holes_field_d / 2 + 1e-7 mm {
                hole holes { h = Circle(center=(i * holes_pitch, j * holes_pitch), diameter=holes_d) }
                Fixed(holes.h)
            }
        }
    }
}
