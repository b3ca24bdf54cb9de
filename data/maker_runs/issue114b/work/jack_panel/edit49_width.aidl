# imported from jack_panel.svg by `aidl import --infer`: edit freely
# recognised: 24 of 24 pieces of outlines and holes in 11 shapes (8 Circle, 2 Rectangle, 1 RoundedRectangle)
# patterns: 1 row, 1 corner
# equal within 1e-07 mm, numbers rounded within 1e-09 mm; the rest stays exact Line/Arc chains
units mm
param width = 240 mm
param height = 80 mm
param corner_radius = 3 mm
param holes_d = 6 mm
param holes_pitch = 20 mm
param holes_n = 4
param holes_y = 25 mm  # its line, from the bottom edge
param corner_hole_d = 3.2 mm
param corner_inset = 5 mm  # from the edges
param window_width = 60 mm
param window_height = 25 mm
param window_2_width = 12 mm
param window_2_height = 20 mm
solid plate {
    body = RoundedRectangle(center=(105, -45), width=width, height=height, corner_radius=corner_radius)
    Fixed(body)
    # row: x about its middle
    for i in range(holes_n) {
        hole holes { h = Circle(center=(105 + (i - (holes_n - 1) / 2) * holes_pitch, -45 - height / 2 + holes_y), diameter=holes_d) }
        Fixed(holes.h)
    }
    # at the corners, corner_inset in from the edges
    hole corner_holes { h = Circle(center=(105 - width / 2 + corner_inset, -45 - height / 2 + corner_inset), diameter=corner_hole_d) }
    CornerPattern(corner_holes, body, inset=corner_inset)
    hole window { h = Rectangle(center=(105 - width / 2 + window_width / 2 + 12, -45 + height / 2 - window_height / 2 - 12), width=window_width, height=window_height) }
    Fixed(window.h)
    hole window_2 { h = Rectangle(center=(105 + width / 2 - window_2_width / 2 - 15, -45), width=window_2_width, height=window_2_height) }
    Fixed(window_2.h)
}
