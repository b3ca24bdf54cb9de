# imported from flange.dxf by `aidl import --infer`: edit freely
# recognised: 5 of 7 pieces of outlines and holes in 5 shapes (5 Circle)
# patterns: 1 bolt circle
# equal within 1e-07 mm, numbers rounded within 1e-09 mm; the rest stays exact Line/Arc chains
units mm
param motor_holes_pcd = 75 mm  # pitch circle diameter
param motor_holes_d = 9 mm
param motor_holes_n = 4  # holes
param motor_holes_angle = 45 deg  # its first hole's, from the x axis
param bore_d = 40 mm
solid part {
    body_s0 = Arc(center=(0, 0), start=(50, 0), end=(-50, 0))
    body_s1 = Arc(center=(0, 0), start=body_s0.end, end=body_s0.start)
    for x in [body_s0.start, body_s1.start] { Fixed(x) }
    body_s0.center.y == 0
    body_s1.center.y == 0
    bore_c = (0, 0)
    # about bore_c, its first hole at motor_holes_angle
    for i in range(motor_holes_n) {
        hole motor_holes { h = Circle(center=polar(bore_c, motor_holes_pcd / 2, motor_holes_angle + i * 360 deg / motor_holes_n), diameter=motor_holes_d) }
        Fixed(motor_holes.h)
    }
    hole bore { h = Circle(center=bore_c, diameter=bore_d) }
    Fixed(bore.h)
}
