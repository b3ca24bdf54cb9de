# imported from terminal_block.dxf by `aidl import --infer`: edit freely
# recognised: 15 of 15 pieces of outlines and holes in 12 shapes (11 Circle, 1 Rectangle)
# patterns: 1 row
# equal within 1e-07 mm, numbers rounded within 1e-09 mm; the rest stays exact Line/Arc chains
# features by the far right and top edges are placed from them: a new width or height keeps their distance to that edge
units mm
param width = 110 mm
param height = 30 mm
param holes_d = 3 mm
param holes_pitch = 7 mm
param holes_n = 10
param holes_x = 10 mm  # its end member, from the left edge
param holes_y = 12 mm  # its line, from the top edge
param hole1_d = 4.5 mm
param hole1_x = 8 mm  # its centre, from the right edge
param hole1_y = 8 mm  # its centre, from the bottom edge
solid plate {
    body = Rectangle(center=(width / 2, height / 2), width=width, height=height)
    Fixed(body)
    # row: x from its end member
    for i in range(holes_n) {
        hole holes { h = Circle(center=(holes_x + i * holes_pitch, height - holes_y), diameter=holes_d) }
        Fixed(holes.h)
    }
    hole hole1 { h = Circle(center=(width - hole1_x, hole1_y), diameter=hole1_d) }
    Fixed(hole1.h)
}
