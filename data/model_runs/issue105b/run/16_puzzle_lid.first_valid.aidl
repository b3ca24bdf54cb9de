# Puzzle box sliding lid, 3 mm plywood: a 100 x 70 mm panel. A half-round finger
# notch 24 mm across (12 mm deep) cut into the front (bottom) edge at its middle.
# Two locking tabs 10 mm wide x 3 mm stick out of the back (top) edge, 20 mm in
# from the left and right ends (tab outer edges). An engraved question mark,
# 18 mm tall, centered on the panel, and a 4 mm hole for the secret pin, 10 mm from
# the right edge and 10 mm above the bottom edge.

units mm
thickness 3 mm

solid lid {
    panel = Rectangle(center=(0, 0), width=100, height=70)

    hole notch {
        c = Circle(center=(0, -35), diameter=24)
    }
    Coincident(notch.c.center, panel.bottom.midpoint)

    solid tab_l {
        r = Rectangle(center=(-25, 36.5), width=10, height=3)
    }
    Above(tab_l, panel)
    tab_l.bb.left == panel.bb.left + 20
    solid tab_r {
        r = Rectangle(center=(25, 36.5), width=10, height=3)
    }
    Above(tab_r, panel)
    tab_r.bb.right == panel.bb.right - 20

    drawing mark {
        q = Text("?", position=(0, 0), size=18, valign="middle")
    }
    CenterInside(mark, panel)

    hole pin {
        c = Circle(center=(40, -25), diameter=4)
    }
    At(pin.c.center, panel.bottom_right, dx=-10, dy=10)
}
