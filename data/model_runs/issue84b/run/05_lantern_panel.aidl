# Lantern panel: a 120 x 160 mm side panel with a 12 mm solid border, a 4 x 5
# grid of hexagonal windows 18 mm across flats at 24 mm pitch, and two 20 x 4 mm
# tabs sticking down from the bottom edge, 30 mm from the centre line.

solid panel {
    body = Rectangle(center=(0, 0), width=120, height=160)
    solid tabs {
        a = Rectangle(center=(-30, -82), width=20, height=4)
        b = Rectangle(center=(30, -82), width=20, height=4)
    }
    hole win { h = RegularPolygon(center=(-36, -48), across_flats=18, sides=6) }
    GridPattern(win, rows=5, cols=4, spacing=(24, 24))
}
