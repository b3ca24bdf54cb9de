# A lamp shade panel: a rectangle with a grid of hexagonal cut-outs.
param w = 150 mm
param h = 200 mm
solid panel {
    body = Rectangle(center=(0, 0), width=w, height=h)
    hole hex { c = RegularPolygon(center=(-60, -85), across_flats=14, sides=6) }
    GridPattern(hex, rows=10, cols=8, col_spacing=17, row_spacing=19)
}
