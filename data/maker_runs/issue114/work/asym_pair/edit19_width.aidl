# imported from asym_pair.svg by `aidl import --infer`: edit freely
# recognised: 6 of 6 pieces of outlines and holes in 3 shapes (2 Circle, 1 Rectangle)
# patterns: 1 equal sizes
# equal within 1e-07 mm, numbers rounded within 1e-09 mm; the rest stays exact Line/Arc chains
# 2 holes in line at x = 30 and 119.97 on either side of the centre line, not mirrored about it (25 and 25.03 from the edges): each kept from its own nearer edge, not a row of 2 from one end
units mm
param width = 180 mm
param height = 40 mm
param holes_d = 6 mm
solid plate {
    body = Rectangle(center=(75, -25), width=width, height=height)
    Fixed(body)
    hole hole1 { h = Circle(center=(75 - width / 2 + 25, -25), diameter=holes_d) }
    Fixed(hole1.h)
    hole hole2 { h = Circle(center=(75 + width / 2 - 25.03, -25), diameter=holes_d) }
    Fixed(hole2.h)
}
