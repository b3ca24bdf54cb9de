# imported from cable_comb2.dxf by `aidl import --infer`: edit freely
# recognised: 6 of 30 pieces of outlines and holes in 3 shapes (2 Circle, 1 Rectangle)
# patterns: 1 notches in a side, 1 mirrored pair
# equal within 1e-07 mm, numbers rounded within 1e-09 mm; the rest stays exact Line/Arc chains
# 2 holes mirrored about the centre line, nearer the side edges than it: each kept from its own edge (`holes_inset`), the far one too
units mm
param width = 150 mm
param height = 40 mm
param round_notches_n = 6
param round_notches_pitch = 20 mm
param round_notches_width = 10 mm
param round_notches_depth = 18 mm
param holes_d = 4.5 mm
param holes_inset = 10 mm  # from the edges
solid part {
    body = Rectangle(center=(width / 2, height / 2), width=width, height=height)
    Fixed(body)
    # 6 notches in the top side, round_notches_pitch apart: a pattern of the side
    for i in range(round_notches_n) {
        hole round_notches {
            h = Rectangle(center=(width / 2 + (i - (round_notches_n - 1) / 2) * round_notches_pitch, height - (round_notches_depth - round_notches_width / 2 - 1 mm) / 2), width=round_notches_width, height=round_notches_depth - round_notches_width / 2 + 1 mm)
            bottom = Circle(center=(width / 2 + (i - (round_notches_n - 1) / 2) * round_notches_pitch, height - (round_notches_depth - round_notches_width / 2)), diameter=round_notches_width)
        }
        for x in [round_notches.h, round_notches.bottom] { Fixed(x) }
    }
    # mirrored about the centre line
    for s in [-1, 1] {
        hole holes { h = Circle(center=(width / 2 + s * (width / 2 - holes_inset), 10), diameter=holes_d) }
        Fixed(holes.h)
    }
}
