# Laptop stand side: a right-angled wedge 240 mm long, 20 mm tall at the front and
# 80 mm tall at the back, with a 20 mm wide x 15 mm deep cable notch (round bottom)
# cut into the bottom edge 40 mm from the back, and a 10 mm front lip 8 mm high.
solid side {
    body = Polygon([(0, 0), (240, 0), (240, 80), (0, 20)])
    solid lip {
        r = Rectangle(bottom_left=(0, 20), width=10, height=8)
    }
    AlignLeft(lip, body)
    lip.bb.bottom == 20   # the lip stands its full 8 mm above the 20 mm front edge
    hole notch {
        n = Slot(center=(200, 0), length=30, width=20, rotation=90)
    }
    notch.n.center.x == body.bb.right - 40
    notch.bb.top == body.bb.bottom + 15
}
