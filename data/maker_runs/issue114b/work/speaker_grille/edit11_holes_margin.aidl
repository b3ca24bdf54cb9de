# imported from speaker_grille.dxf by `aidl import --infer`: edit freely
# recognised: 255 of 255 pieces of outlines and holes in 252 shapes (251 Circle, 1 Rectangle)
# patterns: 1 corner, 1 perforated field
# equal within 1e-07 mm, numbers rounded within 1e-09 mm; the rest stays exact Line/Arc chains
# holes: layer `HOLES` in `PANEL`
# 19 x 13 holes over the plate but for a margin: a perforated field, refilled by a new pitch, hole or plate size
# `holes_margin` = 15 mm, the roundest reading: every margin over 12.5 and up to 15 mm keeps these holes (the drawing fixes no one number); set the one you dimensioned
units mm
param width = 160 mm
param height = 120 mm
param corner_hole_d = 4.5 mm
param corner_inset = 6 mm  # from the edges
param holes_d = 4 mm
param holes_margin = 20 mm  # from the plate's edges to the field's: the roundest of the margins over 12.5 and up to 15 mm, each keeps the holes drawn
param holes_pitch = 7 mm
solid panel {
    body = Rectangle(center=(width / 2, height / 2), width=width, height=height)
    Fixed(body)
    # at the corners, corner_inset in from the edges
    hole corner_holes { h = Circle(center=(corner_inset, corner_inset), diameter=corner_hole_d) }
    CornerPattern(corner_holes, body, inset=corner_inset)
    # a perforated field: the plate less its margin, as many holes as fit, about the plate's centre
    holes_cols = floor(norm((width - 2 * holes_margin - holes_d, 0)) / norm((holes_pitch, 0)) + 1e-6) + 1
    holes_rows = floor(norm((height - 2 * holes_margin - holes_d, 0)) / norm((holes_pitch, 0)) + 1e-6) + 1
    for i in range(holes_cols) {
        for j in range(holes_rows) {
            hole holes { h = Circle(center=(width / 2 + (i - (holes_cols - 1) / 2) * holes_pitch, height / 2 + (j - (holes_rows - 1) / 2) * holes_pitch), diameter=holes_d) }
            Fixed(holes.h)
        }
    }
}
