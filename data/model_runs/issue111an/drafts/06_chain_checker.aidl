# Request (sport): a bicycle chain-wear checker, 3 mm acrylic. A 150 x 22 mm bar,
# ends rounded (R11). At the left end a 3.6 mm round pin hole... no: a fixed hook: a
# 5 mm wide x 6 mm deep notch down from the top edge whose right face sits 6 mm from the
# left end; at the right a second notch whose left face is 10 links + 0.75 % = 
# 12.7 * 10 * 1.0075 = 127.95 mm from the first notch's right face (a worn chain drops
# in). "0.75 %" engraved 4 mm tall between them, and a 5 mm hanging hole 8 mm from the
# right end on the centre line.
thickness 3 mm
kerf 0.15 mm
min_wall 0.3 mm

solid checker {
    # FIX after the first valid program: the R11 end ate the left hook notch
    # (only a ~2 mm step was left); square ends with R3 corners keep it whole
    bar = RoundedRectangle(center=(75, 11), width=150, height=22, corner_radius=3)
    hole hook {
        a = Rectangle(center=(3.5, 19), width=5, height=6)
        b = Rectangle(center=(6 + 127.95 + 2.5, 19), width=5, height=6)
    }
    hole hang { c = Circle(center=(142, 11), diameter=5) }
    drawing label { t = Text("0.75 %", position=(70, 11), size=4, valign="middle") }
    assert hook.b.bb.left - hook.a.bb.right == 127.95 mm, "10 links + 0.75 %"
    assert bar.bb.width == 150 mm, "150 long"
}
