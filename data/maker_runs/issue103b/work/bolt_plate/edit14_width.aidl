# imported from bolt_plate.dxf by `aidl import --infer`: edit freely
# recognised: 14 of 14 pieces of outlines and holes in 7 shapes (6 Circle, 1 RoundedRectangle)
# patterns: 1 bolt circle
# equal within 1e-07 mm, numbers rounded within 1e-09 mm; the rest stays exact Line/Arc chains
units mm
param width = 120 mm
param height = 100 mm
param corner_radius = 6 mm
param bolt_circle_pcd = 60 mm  # pitch circle diameter
param bolt_circle_d = 6.6 mm
param bolt_circle_n = 5  # holes
param bolt_circle_angle = 90 deg  # its first hole's, from the x axis
param bore_d = 30 mm
solid plate {
    body = RoundedRectangle(center=(width / 2, height / 2), width=width, height=height, corner_radius=corner_radius)
    Fixed(body)
    bore_c = (width / 2, height / 2)
    # about bore_c, its first hole at bolt_circle_angle
    for i in range(bolt_circle_n) {
        hole bolt_circle { h = Circle(center=polar(bore_c, bolt_circle_pcd / 2, bolt_circle_angle + i * 360 deg / bolt_circle_n), diameter=bolt_circle_d) }
        Fixed(bolt_circle.h)
    }
    hole bore { h = Circle(center=bore_c, diameter=bore_d) }
    Fixed(bore.h)
}
