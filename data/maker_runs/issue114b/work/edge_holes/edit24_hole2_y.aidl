# imported from edge_holes.dxf by `aidl import --infer`: edit freely
# recognised: 6 of 6 pieces of outlines and holes in 3 shapes (2 Circle, 1 Rectangle)
# equal within 1e-07 mm, numbers rounded within 1e-09 mm; the rest stays exact Line/Arc chains
# holes: layer `HOLES` in `OUTLINE`
# features by the far right and top edges are placed from them: a new width or height keeps their distance to that edge
units mm
param width = 150 mm
param height = 80 mm
param hole1_d = 10 mm
param hole1_x = 22 mm  # its centre, from the left edge
param hole2_d = 6 mm
param hole2_x = 18 mm  # its centre, from the right edge
param hole2_y = 20 mm  # its centre, from the top edge
solid plate {
    body = Rectangle(center=(width / 2, height / 2), width=width, height=height)
    Fixed(body)
    hole hole1 { h = Circle(center=(hole1_x, height / 2), diameter=hole1_d) }
    Fixed(hole1.h)
    hole hole2 { h = Circle(center=(width - hole2_x, height - hole2_y), diameter=hole2_d) }
    Fixed(hole2.h)
}
