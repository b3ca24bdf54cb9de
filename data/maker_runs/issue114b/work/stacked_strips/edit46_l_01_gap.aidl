# imported from stacked_strips.dxf by `aidl import --infer`: edit freely
# recognised: 11 of 11 pieces of outlines and holes in 5 shapes (3 Circle, 2 Rectangle)
# patterns: 1 mirrored pair
# equal within 1e-07 mm, numbers rounded within 1e-09 mm; the rest stays exact Line/Arc chains
# 2 holes mirrored about the centre line, nearer the side edges than it: each kept from its own edge (`holes_inset`), the far one too
# `l_01` beside `l_02`: placed from its top edge by `l_01_gap`
units mm
param l_02_width = 150 mm
param l_02_height = 20 mm
param l_02_holes_d = 5 mm
param l_02_holes_inset = 10 mm  # from the edges
param l_01_gap = 15 mm  # from l_02's top edge
param l_01_width = 120 mm
param l_01_height = 30 mm
param l_01_bore_d = 10 mm
assembly drawing_import {
    solid l_02 {
        body = Rectangle(center=(l_02_width / 2, l_02_height / 2), width=l_02_width, height=l_02_height)
        Fixed(body)
        # mirrored about the centre line
        for s in [-1, 1] {
            hole holes { h = Circle(center=(l_02_width / 2 + s * (l_02_width / 2 - l_02_holes_inset), l_02_height / 2), diameter=l_02_holes_d) }
            Fixed(holes.h)
        }
    }
    solid l_01 {
        body = Rectangle(center=(l_01_width / 2, 28 + (l_02_height + l_01_gap - 28) + l_01_height / 2), width=l_01_width, height=l_01_height)
        Fixed(body)
        hole bore { h = Circle(center=(l_01_width / 2, 28 + (l_02_height + l_01_gap - 28) + l_01_height / 2), diameter=l_01_bore_d) }
        Fixed(bore.h)
    }
    for p in [l_02, l_01] { Fixed(p) }
}
