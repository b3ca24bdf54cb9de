# imported from l_brackets_pair.dxf by `aidl import --infer`: edit freely
# recognised: 12 of 12 pieces of outlines and holes in 2 shapes (2 Polygon)
# patterns: 2 profile
# equal within 1e-07 mm, numbers rounded within 1e-09 mm; the rest stays exact Line/Arc chains
# `l_01` beside `l_02`: placed from its right edge by `l_01_gap`
units mm
param l_02_width = 50 mm
param l_02_height = 40 mm
param l_02_wall = 8 mm
param l_01_gap = 15 mm  # from l_02's right edge
param l_01_width = 70 mm
param l_01_height = 40 mm
param l_01_wall = 8 mm
assembly drawing_import {
    solid l_02 {
        # a profile of 6 corners at right angles: its faces by the edges and the walls' thickness
        body = Polygon([(0, 0), (l_02_width, 0), (l_02_width, l_02_wall), (l_02_wall, l_02_wall), (l_02_wall, l_02_height), (0, l_02_height)])
        Fixed(body)
    }
    solid l_01 {
        # a profile of 6 corners at right angles: its faces by the edges and the walls' thickness
        body = Polygon([(65 + (l_02_width + l_01_gap - 65), 0), (65 + (l_02_width + l_01_gap - 65) + l_01_width, 0), (65 + (l_02_width + l_01_gap - 65) + l_01_width, l_01_wall), (65 + (l_02_width + l_01_gap - 65) + l_01_wall, l_01_wall), (65 + (l_02_width + l_01_gap - 65) + l_01_wall, l_01_height), (65 + (l_02_width + l_01_gap - 65), l_01_height)])
        Fixed(body)
    }
    for p in [l_02, l_01] { Fixed(p) }
}
