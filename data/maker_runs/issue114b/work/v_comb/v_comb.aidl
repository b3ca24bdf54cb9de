# imported from v_comb.dxf by `aidl import --infer`: edit freely
# recognised: 6 of 30 pieces of outlines and holes in 3 shapes (2 Circle, 1 Rectangle)
# patterns: 1 notches in a side, 1 mirrored pair
# equal within 1e-07 mm, numbers rounded within 1e-09 mm; the rest stays exact Line/Arc chains
# 2 holes mirrored about the centre line, nearer the side edges than it: each kept from its own edge (`holes_inset`), the far one too
units mm
param width = 160 mm
param height = 40 mm
param v_notches_n = 8
param v_notches_pitch = 16 mm
param v_notches_width = 8 mm
param v_notches_depth = 12 mm
param holes_d = 4.5 mm
param holes_inset = 10 mm  # from the edges
solid plate {
    body = Rectangle(center=(width / 2, height / 2), width=width, height=height)
    Fixed(body)
    # 8 notches in the top side, v_notches_pitch apart: a pattern of the side
    for i in range(v_notches_n) {
        hole v_notches { h = Polygon([(width / 2 + (i - (v_notches_n - 1) / 2) * v_notches_pitch - v_notches_width / 2 * (v_notches_depth + 1 mm) / v_notches_depth, height + 1 mm), (width / 2 + (i - (v_notches_n - 1) / 2) * v_notches_pitch, height - v_notches_depth), (width / 2 + (i - (v_notches_n - 1) / 2) * v_notches_pitch + v_notches_width / 2 * (v_notches_depth + 1 mm) / v_notches_depth, height + 1 mm)]) }
        Fixed(v_notches.h)
    }
    # mirrored about the centre line
    for s in [-1, 1] {
        hole holes { h = Circle(center=(width / 2 + s * (width / 2 - holes_inset), 10), diameter=holes_d) }
        Fixed(holes.h)
    }
}
