# imported from bracket_pair.dxf by `aidl import --infer`: edit freely
# recognised: 11 of 11 pieces of outlines and holes in 5 shapes (3 Circle, 2 Rectangle)
# patterns: 1 mirrored pair
# equal within 1e-07 mm, numbers rounded within 1e-09 mm; the rest stays exact Line/Arc chains
# `l_02` beside `l_01`: placed from its right edge by `l_02_gap`
units mm
param l_01_width = 60 mm
param l_01_height = 40 mm
param l_01_holes_d = 5 mm
param l_01_holes_spacing = 30 mm
param l_02_gap = 10 mm  # from l_01's right edge
param l_02_width = 50 mm
param l_02_height = 40 mm
param l_02_bore_d = 8 mm
assembly drawing_import {
    solid l_01 {
        body = Rectangle(center=(l_01_width / 2, l_01_height / 2), width=l_01_width, height=l_01_height)
        Fixed(body)
        # mirrored about the centre line
        for s in [-1, 1] {
            hole holes { h = Circle(center=(l_01_width / 2 + s * l_01_holes_spacing / 2, l_01_height / 2), diameter=l_01_holes_d) }
            Fixed(holes.h)
        }
    }
    solid l_02 {
        body = Rectangle(center=(70 + (l_01_width + l_02_gap - 70) + l_02_width / 2, l_02_height / 2), width=l_02_width, height=l_02_height)
        Fixed(body)
        hole bore { h = Circle(center=(70 + (l_01_width + l_02_gap - 70) + l_02_width / 2, l_02_height / 2), diameter=l_02_bore_d) }
        Fixed(bore.h)
    }
    for p in [l_01, l_02] { Fixed(p) }
}
