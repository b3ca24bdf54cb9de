# Request (crafts): English paper piecing window templates in 3 mm clear acrylic, for
# hexagons of 3/4 in, 1 in, 1 1/4 in and 1 1/2 in sides. Each template is a hexagon frame with
# flats at top and bottom: the window is the finished hexagon (the named side length), the
# outer edge is the window grown by a 3/8 in seam allowance with sharp (mitred) corners. The
# size ("3/4 in", "1 in", "1 1/4 in", "1 1/2 in") is engraved 0.16 in tall in the middle of
# the bottom band, and a 1/8 in hole in the right-hand corner of the frame, halfway across it,
# lets them hang on a ring. Templates 1/4 in apart on the sheet.

units in
thickness 3 mm

seam = 3/8
sides_in = [0.75, 1, 1.25, 1.5]
labels = ["3/4 in", "1 in", "1 1/4 in", "1 1/2 in"]

def hex_window(side=1, label="1 in") -> solid {
    outer = Offset(RegularPolygon(center=(0, 0), side=side, sides=6), seam, join="miter")
    hole window {
        w = RegularPolygon(center=(0, 0), side=side, sides=6)
    }
    drawing size {
        t = Text(label, position=(0, -(side * sqrt(3) / 2 + seam / 2)), size=0.16,
                 valign="middle")
    }
    hole ring {
        # the frame's right corner runs from the window's vertex to the outer vertex
        c = Circle(center=(side + seam / sin(60 deg) / 2, 0), diameter=1/8)
    }
}

assembly epp_set {
    for i in range(4) {
        tpl = hex_window(side=sides_in[i], label=labels[i])
    }
    for i in range(1, 4) {
        RightOf(tpl[i], tpl[i - 1], gap=1/4)
        AlignBottom(tpl[i], tpl[0])
    }

    # the request's numbers
    assert len(tpl) == 4, "four templates"
    assert tpl[0].window.w.edges[0].length == 0.75 in and tpl[3].window.w.edges[0].length == 1.5 in,
        "sizes"
    assert tpl[1].outer.bb.height - tpl[1].window.w.bb.height == 2 * 0.375 in,
        "3/8 in seam allowance"
    assert tpl[2].size.t.text == "1 1/4 in", "label matches the size"
    assert tpl[0].ring.c.diameter == 0.125 in, "1/8 in ring hole"
}
