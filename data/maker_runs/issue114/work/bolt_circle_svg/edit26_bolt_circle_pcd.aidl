# imported from bolt_circle_svg.svg by `aidl import --infer`: edit freely
# recognised: 6 of 8 pieces of outlines and holes in 6 shapes (6 Circle)
# patterns: 1 bolt circle
# equal within 1e-07 mm, numbers rounded within 1e-09 mm; the rest stays exact Line/Arc chains
# 5 holes evenly round a centre to the drawing's own precision (1e-06 mm): one bolt circle, its holes written on it exactly
units mm
param bolt_circle_pcd = 90 mm  # pitch circle diameter
param bolt_circle_d = 6.6 mm
param bolt_circle_n = 5  # holes
param bolt_circle_angle = 90 deg  # its first hole's, from the x axis
param bore_d = 40 mm
solid part {
    body_s0 = Arc(center=(60, -60), start=(115, -60), end=(5, -60))
    body_s1 = Arc(center=(60, -60), start=body_s0.end, end=body_s0.start)
    for x in [body_s0.start, body_s1.start] { Fixed(x) }
    body_s0.center.y == -60
    body_s1.center.y == -60
    bore_c = (60, -60)
    # about bore_c, its first hole at bolt_circle_angle
    for i in range(bolt_circle_n) {
        hole bolt_circle { h = Circle(center=polar(bore_c, bolt_circle_pcd / 2, bolt_circle_angle + i * 360 deg / bolt_circle_n), diameter=bolt_circle_d) }
        Fixed(bolt_circle.h)
    }
    hole bore { h = Circle(center=bore_c, diameter=bore_d) }
    Fixed(bore.h)
}
