# imported from lid_svg.svg by `aidl import --infer`: edit freely
# recognised: 16 of 16 pieces of outlines and holes in 6 shapes (4 Circle, 1 RoundedRectangle, 1 Rectangle)
# patterns: 1 corner
# equal within 1e-07 mm, numbers rounded within 1e-09 mm; the rest stays exact Line/Arc chains
# 4 holes both about window_c and at the corners: read as at the corners (their inset kept when the plate grows)
units mm
param width = 120 mm
param height = 80 mm
param corner_radius = 6 mm
param corner_hole_d = 3.4 mm
param corner_inset = 6 mm  # from the edges
param window_width = 40 mm
param window_height = 20 mm
solid plate {
    body = RoundedRectangle(center=(65, -45), width=width, height=height, corner_radius=corner_radius)
    Fixed(body)
    window_c = (65, -45)
    # at the corners, corner_inset in from the edges
    hole corner_holes { h = Circle(center=(65 - width / 2 + corner_inset, -45 - height / 2 + corner_inset), diameter=corner_hole_d) }
    CornerPattern(corner_holes, body, inset=corner_inset)
    hole window { h = Rectangle(center=window_c, width=window_width, height=window_height) }
    Fixed(window.h)
}
