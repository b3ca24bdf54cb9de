# imported from pcb_board.dxf by `aidl import --infer`: edit freely
# recognised: 12 of 12 pieces of outlines and holes in 5 shapes (4 Circle, 1 RoundedRectangle)
# patterns: 1 corner
# equal within 1e-07 mm, numbers rounded within 1e-09 mm; the rest stays exact Line/Arc chains
units mm
param width = 64 mm
param height = 42 mm
param corner_radius = 3 mm
param corner_hole_d = 3.2 mm
param corner_inset = 3.5 mm  # from the edges
assembly drawing_import {
    solid edge_cuts {
        body = RoundedRectangle(center=(width / 2, height / 2), width=width, height=height, corner_radius=corner_radius)
        Fixed(body)
        # at the corners, corner_inset in from the edges
        hole corner_holes {
            h = Circle(center=(corner_inset, corner_inset), diameter=corner_hole_d)
        }
        CornerPattern(corner_holes, body, inset=corner_inset)
    }
    drawing f_silks {
        t1 = Text("SENSOR-BOARD rev A", position=(8, 20), size=1.5, anchor="start", valign="baseline")
        Fixed(t1)
    }
    for p in [edge_cuts, f_silks] {
        Fixed(p)
    }
    CutInto(f_silks, edge_cuts)
}
