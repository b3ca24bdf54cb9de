# imported from stacked_plates.dxf by `aidl import --infer`: edit freely
# recognised: 15 of 15 pieces of outlines and holes in 6 shapes (3 Rectangle, 3 Circle)
# equal within 1e-07 mm, numbers rounded within 1e-09 mm; the rest stays exact Line/Arc chains
# `l_01` beside `l_02`: placed from its top edge by `l_01_gap`
# `l_03` beside `l_01`: placed from its top edge by `l_03_gap`
units mm
param l_02_width = 100 mm
param l_02_height = 30 mm
param l_02_bore_d = 8 mm
param l_01_gap = 12 mm  # from l_02's top edge
param l_01_width = 90 mm
param l_01_height = 40 mm
param l_01_bore_d = 6 mm
param l_03_gap = 10 mm  # from l_01's top edge
param l_03_width = 70 mm
param l_03_height = 25 mm
param l_03_bore_d = 5 mm
assembly drawing_import {
    solid l_02 {
        body = Rectangle(center=(l_02_width / 2, l_02_height / 2), width=l_02_width, height=l_02_height)
        Fixed(body)
        hole bore { h = Circle(center=(l_02_width / 2, l_02_height / 2), diameter=l_02_bore_d) }
        Fixed(bore.h)
    }
    solid l_01 {
        body = Rectangle(center=(l_01_width / 2, 36 + (l_02_height + l_01_gap - 36) + l_01_height / 2), width=l_01_width, height=l_01_height)
        Fixed(body)
        hole bore { h = Circle(center=(l_01_width / 2, 36 + (l_02_height + l_01_gap - 36) + l_01_height / 2), diameter=l_01_bore_d) }
        Fixed(bore.h)
    }
    solid l_03 {
        body = Rectangle(center=(l_03_width / 2, 86 + (36 + (l_02_height + l_01_gap - 36) + l_01_height + l_03_gap - 86) + l_03_height / 2), width=l_03_width, height=l_03_height)
        Fixed(body)
        hole bore { h = Circle(center=(l_03_width / 2, 86 + (36 + (l_02_height + l_01_gap - 36) + l_01_height + l_03_gap - 86) + l_03_height / 2), diameter=l_03_bore_d) }
        Fixed(bore.h)
    }
    for p in [l_02, l_01, l_03] { Fixed(p) }
}
