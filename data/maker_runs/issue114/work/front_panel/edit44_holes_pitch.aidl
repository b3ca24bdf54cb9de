# imported from front_panel.dxf by `aidl import --infer`: edit freely
# recognised: 19 of 19 pieces of outlines and holes in 9 shapes (7 Circle, 1 RoundedRectangle, 1 Rectangle)
# patterns: 1 row, 1 corner
# equal within 1e-07 mm, numbers rounded within 1e-09 mm; the rest stays exact Line/Arc chains
# holes: layer `HOLES` in `PANEL`
# features by the far right edge are placed from it: a new width keeps their distance to that edge
units mm
param width = 180 mm
param height = 90 mm
param corner_radius = 3 mm
param holes_d = 7 mm
param holes_pitch = 25 mm
param holes_n = 3
param corner_hole_d = 3.2 mm
param corner_inset = 5 mm  # from the edges
param window_width = 60 mm
param window_height = 30 mm
solid panel {
    body = RoundedRectangle(center=(width / 2, height / 2), width=width, height=height, corner_radius=corner_radius)
    Fixed(body)
    # row: x from its end member
    for i in range(holes_n) {
        hole holes { h = Circle(center=(width - 20 + (i - (holes_n - 1)) * holes_pitch, 25), diameter=holes_d) }
        Fixed(holes.h)
    }
    # at the corners, corner_inset in from the edges
    hole corner_holes { h = Circle(center=(corner_inset, corner_inset), diameter=corner_hole_d) }
    CornerPattern(corner_holes, body, inset=corner_inset)
    hole window { h = Rectangle(center=(window_width / 2 + 10, height - window_height / 2 - 15), width=window_width, height=window_height) }
    Fixed(window.h)
}
