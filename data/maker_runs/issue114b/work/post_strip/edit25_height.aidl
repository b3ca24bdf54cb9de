# imported from post_strip.dxf by `aidl import --infer`: edit freely
# recognised: 6 of 6 pieces of outlines and holes in 3 shapes (2 Circle, 1 Rectangle)
# patterns: 1 equal sizes
# equal within 1e-07 mm, numbers rounded within 1e-09 mm; the rest stays exact Line/Arc chains
# 2 holes in line at y = 15 and 140 on either side of the centre line, not mirrored about it (15 and 20 from the edges): each kept from its own nearer edge, not a row of 2 from one end
# features by the far top edge are placed from it: a new height keeps their distance to that edge
units mm
param width = 30 mm
param height = 200 mm
param holes_d = 5 mm
param hole1_y = 15 mm  # its centre, from the bottom edge
param hole2_y = 20 mm  # its centre, from the top edge
solid plate {
    body = Rectangle(center=(width / 2, height / 2), width=width, height=height)
    Fixed(body)
    hole hole1 { h = Circle(center=(width / 2, hole1_y), diameter=holes_d) }
    Fixed(hole1.h)
    hole hole2 { h = Circle(center=(width / 2, height - hole2_y), diameter=holes_d) }
    Fixed(hole2.h)
}
