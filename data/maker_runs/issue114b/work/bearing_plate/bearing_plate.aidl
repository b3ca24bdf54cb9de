# imported from bearing_plate.svg by `aidl import --infer`: edit freely
# recognised: 12 of 12 pieces of outlines and holes in 9 shapes (8 Circle, 1 Rectangle)
# patterns: 1 bolt circle, 1 corner
# equal within 1e-07 mm, numbers rounded within 1e-09 mm; the rest stays exact Line/Arc chains
# 3 holes evenly round a centre to the drawing's own precision (1e-06 mm): one bolt circle, its holes written on it exactly
# 4 holes both about bore_c and at the corners: read as at the corners (their inset kept when the plate grows)
units mm
param width = 90 mm
param height = 90 mm
param bolt_circle_pcd = 48 mm  # pitch circle diameter
param bolt_circle_d = 5.5 mm
param bolt_circle_n = 3  # holes
param bolt_circle_angle = 90 deg  # its first hole's, from the x axis
param corner_hole_d = 4.5 mm
param corner_inset = 7 mm  # from the edges
param bore_d = 28 mm
solid plate {
    body = Rectangle(center=(50, -50), width=width, height=height)
    Fixed(body)
    bore_c = (50, -50)
    # about bore_c, its first hole at bolt_circle_angle
    for i in range(bolt_circle_n) {
        hole bolt_circle { h = Circle(center=polar(bore_c, bolt_circle_pcd / 2, bolt_circle_angle + i * 360 deg / bolt_circle_n), diameter=bolt_circle_d) }
        Fixed(bolt_circle.h)
    }
    # at the corners, corner_inset in from the edges
    hole corner_holes { h = Circle(center=(50 - width / 2 + corner_inset, -50 - height / 2 + corner_inset), diameter=corner_hole_d) }
    CornerPattern(corner_holes, body, inset=corner_inset)
    hole bore { h = Circle(center=bore_c, diameter=bore_d) }
    Fixed(bore.h)
}
