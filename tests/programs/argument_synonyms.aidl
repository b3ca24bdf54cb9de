// Issue 14: argument names models write without being told; each means a canonical one.
units mm

solid plate {
    body = Rectangle(center=(0, 0), w=80, h=50)
    hole bore {
        c = Circle((-25, 0), r=6)
    }
    hole pin {
        p = Circle(center=(25, 0), d=12)
    }
    hole slot {
        s = Slot(start=(-10, -15), end=(10, -15), width=6)
    }
    axis = Line((0, -30), (0, 30), construction=true)
    Symmetric(bore.c, pin.p, axis=axis)
    top_rail = Line((-40, 25), (40, 25), construction=true)
    guide = Line((-30, 14), (30, 13), construction=true)
    Distance(top_rail, guide, 10)
    Fillet(corners=[body.top, body.right], r=4)
    Chamfer(corner=body.bottom_left, size=3)
    drawing label {
        t = Text(text="PLATE", center=(0, 15), height=5)
    }
}
