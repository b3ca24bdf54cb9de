# imported from centred_plate.dxf by `aidl import --infer`: edit freely
# recognised: 16 of 16 pieces of outlines and holes in 6 shapes (4 Circle, 1 RoundedRectangle, 1 Rectangle)
# patterns: 1 corner
# equal within 1e-07 mm, numbers rounded within 1e-09 mm; the rest stays exact Line/Arc chains
# 4 holes both about window_c and at the corners: read as at the corners (their inset kept when the plate grows)
units mm
param width = 140 mm
param height = 70 mm
param corner_radius = 4 mm
param corner_hole_d = 3.5 mm
param corner_inset_x = 8 mm  # from the left and right edges
param corner_inset_y = 6 mm  # from the top and bottom edges
param window_width = 40 mm
param window_height = 25 mm
solid plate {
    body = RoundedRectangle(center=(0, 0), width=width, height=height, corner_radius=corner_radius)
    Fixed(body)
    window_c = (0, 0)
    # at the corners, corner_inset_x and corner_inset_y in from the edges
    hole corner_holes { h = Circle(center=(-width / 2 + corner_inset_x, -height / 2 + corner_inset_y), diameter=corner_hole_d) }
    CornerPattern(corner_holes, body, inset=(corner_inset_x, corner_inset_y))
    hole window { h = Rectangle(center=window_c, width=window_width, height=window_height) }
    Fixed(window.h)
}
