# imported from vent_plate.dxf by `aidl import --infer`: edit freely
# recognised: 239 of 239 pieces of outlines and holes in 232 shapes (231 Circle, 1 RoundedRectangle)
# patterns: 1 perforated field
# equal within 1e-07 mm, numbers rounded within 1e-09 mm; the rest stays exact Line/Arc chains
# 21 x 11 holes over the plate but for a margin: a perforated field, refilled by a new pitch, hole or plate size
# `holes_margin` = 15 mm, the roundest reading: every margin over 12 and up to 17 mm keeps these holes (the drawing fixes no one number); set the one you dimensioned
units mm
param width = 240 mm
param height = 140 mm
param corner_radius = 4 mm
param holes_d = 6 mm
param holes_margin = 15 mm  # from the plate's edges to the field's: the roundest of the margins over 12 and up to 17 mm, each keeps the holes drawn
param holes_pitch = 12 mm
solid plate {
    body = RoundedRectangle(center=(width / 2, height / 2), width=width, height=height, corner_radius=corner_radius)
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
}
