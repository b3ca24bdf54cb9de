# imported from terminal_row.dxf by `aidl import --infer`: edit freely
# recognised: 11 of 11 pieces of outlines and holes in 8 shapes (7 Circle, 1 Rectangle)
# patterns: 1 row with a gap list
# equal within 1e-07 mm, numbers rounded within 1e-09 mm; the rest stays exact Line/Arc chains
# a 4 mm hole at (18, 15) completes a pattern of 3.5 mm holes: one pattern, that hole its own size (`_odd_d`)
units mm
param width = 120 mm
param height = 30 mm
param holes_d = 3.5 mm
param holes_pitch = 10 mm
param holes_n = 8
param holes_odd_d = 4 mm
solid plate {
    body = Rectangle(center=(width / 2, height / 2), width=width, height=height)
    Fixed(body)
    # row: x about its middle
    for i in range(holes_n) {
        if not (i == 3) {     # the gap: 1 hole of the row left out, as drawn
            hole holes { h = Circle(center=(width / 2 + (i - (holes_n - 1) / 2) * holes_pitch, height / 2), diameter=(holes_odd_d if i == 0 else holes_d)) }
            Fixed(holes.h)
        }
    }
}
