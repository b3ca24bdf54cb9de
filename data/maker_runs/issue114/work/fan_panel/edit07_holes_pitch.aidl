# imported from fan_panel.dxf by `aidl import --infer`: edit freely
# recognised: 233 of 233 pieces of outlines and holes in 230 shapes (229 Circle, 1 Rectangle)
# patterns: 1 perforated field, 1 corner
# equal within 1e-07 mm, numbers rounded within 1e-09 mm; the rest stays exact Line/Arc chains
# 15 x 15 holes over the plate but for a margin: a perforated field, refilled by a new pitch, hole or plate size
units mm
param width = 120 mm
param height = 120 mm
param holes_d = 4.5 mm
param holes_margin = 15 mm  # from the plate's edges to the field's
param holes_pitch = 7 mm
param corner_hole_d = 4.3 mm
param corner_inset = 7.5 mm  # from the edges
solid plate {
    body = Rectangle(center=(width / 2, height / 2), width=width, height=height)
    Fixed(body)
    # a perforated field: the plate less its margin, as many holes as fit, about the plate's centre
    holes_cols = floor(norm((width - 2 * holes_margin - holes_d, 0)) / norm((holes_pitch, 0)) + 1e-6) + 1
    holes_rows = floor(norm((height - 2 * holes_margin - holes_d, 0)) / norm((holes_pitch, 0)) + 1e-6) + 1
    for i in range(holes_cols) {
        for j in range(holes_rows) {
            hole holes { h = Circle(center=(width / 2 + (i - (holes_cols - 1) / 2) * holes_pitch, height / 2 + (j - (holes_rows - 1) / 2) * holes_pitch), diameter=holes_d) }
            Fixed(holes.h)
        }
    }
    # at the corners, corner_inset in from the edges
    hole corner_holes { h = Circle(center=(corner_inset, corner_inset), diameter=corner_hole_d) }
    CornerPattern(corner_holes, body, inset=corner_inset)
}
