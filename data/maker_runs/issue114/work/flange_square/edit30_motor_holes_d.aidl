# imported from flange_square.dxf by `aidl import --infer`: edit freely
# recognised: 13 of 13 pieces of outlines and holes in 6 shapes (5 Circle, 1 RoundedRectangle)
# patterns: 1 bolt circle
# equal within 1e-07 mm, numbers rounded within 1e-09 mm; the rest stays exact Line/Arc chains
units mm
param width = 100 mm
param height = 100 mm
param corner_radius = 10 mm
param motor_holes_pcd = 80 mm  # pitch circle diameter
param motor_holes_d = 9 mm
param motor_holes_n = 4  # holes
param motor_holes_angle = 45 deg  # its first hole's, from the x axis
param bore_d = 50 mm
solid plate {
    body = RoundedRectangle(center=(0, 0), width=width, height=height, corner_radius=corner_radius)
    Fixed(body)
    bore_c = (0, 0)
    # about bore_c, its first hole at motor_holes_angle
    for i in range(motor_holes_n) {
        hole motor_holes { h = Circle(center=polar(bore_c, motor_holes_pcd / 2, motor_holes_angle + i * 360 deg / motor_holes_n), diameter=motor_holes_d) }
        Fixed(motor_holes.h)
    }
    hole bore { h = Circle(center=bore_c, diameter=bore_d) }
    Fixed(bore.h)
}
