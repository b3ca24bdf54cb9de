# imported from stacked_brackets.dxf by `aidl import --infer`: edit freely
# recognised: 14 of 14 pieces of outlines and holes in 5 shapes (2 Rectangle, 2 Circle, 1 Slot)
# patterns: 1 mirrored pair
# equal within 1e-07 mm, numbers rounded within 1e-09 mm; the rest stays exact Line/Arc chains
units mm
param l_01_width = 80 mm
param l_01_height = 40 mm
param l_01_slot_length = 30 mm
param l_01_slot_width = 6 mm
param l_02_width = 80 mm
param l_02_height = 35 mm
param l_02_holes_d = 5 mm
param l_02_holes_inset = 10 mm  # from the edges
assembly drawing_import {
    solid l_01 {
        body = Rectangle(center=(l_01_width / 2, 58), width=l_01_width, height=l_01_height)
        Fixed(body)
        hole slot { h = Slot(center=(l_01_width / 2, 58), length=l_01_slot_length, width=l_01_slot_width) }
        Fixed(slot.h)
    }
    solid l_02 {
        body = Rectangle(center=(l_02_width / 2, l_02_height / 2), width=l_02_width, height=l_02_height)
        Fixed(body)
        # mirrored about the centre line
        for s in [-1, 1] {
            hole holes { h = Circle(center=(l_02_width / 2 + s * (l_02_width / 2 - l_02_holes_inset), l_02_height / 2), diameter=l_02_holes_d) }
            Fixed(holes.h)
        }
    }
    for p in [l_01, l_02] { Fixed(p) }
}
