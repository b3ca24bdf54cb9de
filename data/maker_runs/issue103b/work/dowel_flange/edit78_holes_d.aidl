# imported from dowel_flange.svg by `aidl import --infer`: edit freely
# recognised: 7 of 9 pieces of outlines and holes in 7 shapes (7 Circle)
# patterns: 1 equal sizes
# equal within 1e-07 mm, numbers rounded within 1e-09 mm; the rest stays exact Line/Arc chains
units mm
param holes_d = 6.6 mm
param hole1_d = 30 mm
param hole2_d = 6 mm
solid part {
    body_s0 = Arc(center=(50, -50), start=(95, -50), end=(5, -50))
    body_s1 = Arc(center=(50, -50), start=body_s0.end, end=body_s0.start)
    for x in [body_s0.start, body_s1.start] { Fixed(x) }
    body_s0.center.y == -50
    body_s1.center.y == -50
    for c in [(17, -50), (33.5, -78.578838), (33.5, -21.421162), (66.5, -78.578838), (66.5, -21.421162)] {
        hole holes { h = Circle(center=c, diameter=holes_d) }
        Fixed(holes.h)
    }
    hole hole1 { h = Circle(center=(50, -50), diameter=hole1_d) }
    Fixed(hole1.h)
    hole hole2 { h = Circle(center=(83, -50), diameter=hole2_d) }
    Fixed(hole2.h)
}
