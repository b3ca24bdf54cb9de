# imported from terminal_strip.dxf by `aidl import --infer`: edit freely
# recognised: 15 of 15 pieces of outlines and holes in 12 shapes (11 Circle, 1 Rectangle)
# patterns: 1 row with a gap list
# equal within 1e-07 mm, numbers rounded within 1e-09 mm; the rest stays exact Line/Arc chains
# holes: layer `HOLES` in `STRIP`
# a 5 mm hole at (118, 12.5) completes a pattern of 3.5 mm holes: one pattern, that hole its own size (`_odd_d`)
units mm
param width = 130 mm
param height = 25 mm
param holes_d = 3.5 mm
param holes_pitch = 10 mm
param holes_n = 13
param holes_odd_d = 5 mm
solid strip {
    body = Rectangle(center=(width / 2, height / 2), width=width, height=height)
    Fixed(body)
    # row: x from its end member
    for i in range(holes_n) {
        if not (i == 10 or i == 11) {     # the gaps: 2 holes of the row left out, as drawn
            hole holes { h = Circle(center=(10 + i * holes_pitch, height / 2), diameter=(holes_odd_d if i == 12 else holes_d)) }
            Fixed(holes.h)
        }
    }
}
