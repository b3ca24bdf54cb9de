# imported from pipe_flange.dxf by `aidl import --infer`: edit freely
# recognised: 9 of 11 pieces of outlines and holes in 9 shapes (9 Circle)
# patterns: 1 bolt circle
# equal within 1e-07 mm, numbers rounded within 1e-09 mm; the rest stays exact Line/Arc chains
units mm
param bolt_circle_pcd = 120 mm  # pitch circle diameter
param bolt_circle_d = 14 mm
param bolt_circle_n = 8  # holes
param bolt_circle_angle = 22.5 deg  # its first hole's, from the x axis
param bore_d = 60 mm
solid part {
    body_s0 = Arc(center=(0, 0), start=(75, 0), end=(-75, 0))
    body_s1 = Arc(center=(0, 0), start=body_s0.end, end=body_s0.start)
    for x in [body_s0.start, body_s1.start] { Fixed(x) }
    body_s0.center.y == 0
    body_s1.center.y == 0
    bore_c = (0, 0)
    # about bore_c, its first hole at bolt_circle_angle
    for i in range(bolt_circle_n) {
        hole bolt_circle { h = Circle(center=polar(bore_c, bolt_circle_pcd / 2, bolt_circle_angle + i * 360 deg / bolt_circle_n), diameter=bolt_circle_d) }
        Fixed(bolt_circle.h)
    }
    hole bore { h = Circle(center=bore_c, diameter=bore_d) }
    Fixed(bore.h)
}
