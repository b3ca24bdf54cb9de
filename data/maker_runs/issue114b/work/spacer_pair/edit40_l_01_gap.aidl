# imported from spacer_pair.dxf by `aidl import --infer`: edit freely
# recognised: 10 of 10 pieces of outlines and holes in 4 shapes (2 Rectangle, 2 Circle)
# equal within 1e-07 mm, numbers rounded within 1e-09 mm; the rest stays exact Line/Arc chains
# `l_01` beside `l_02`: placed from its right edge by `l_01_gap`
units mm
param l_02_width = 40 mm
param l_02_height = 30 mm
param l_02_bore_d = 6 mm
param l_01_gap = 20 mm  # from l_02's right edge
param l_01_width = 50 mm
param l_01_height = 30 mm
param l_01_bore_d = 8 mm
assembly drawing_import {
    solid l_02 {
        body = Rectangle(center=(l_02_width / 2, l_02_height / 2), width=l_02_width, height=l_02_height)
        Fixed(body)
        hole bore { h = Circle(center=(l_02_width / 2, l_02_height / 2), diameter=l_02_bore_d) }
        Fixed(bore.h)
    }
    solid l_01 {
        body = Rectangle(center=(52 + (l_02_width + l_01_gap - 52) + l_01_width / 2, l_01_height / 2), width=l_01_width, height=l_01_height)
        Fixed(body)
        hole bore { h = Circle(center=(52 + (l_02_width + l_01_gap - 52) + l_01_width / 2, l_01_height / 2), diameter=l_01_bore_d) }
        Fixed(bore.h)
    }
    for p in [l_02, l_01] { Fixed(p) }
}
