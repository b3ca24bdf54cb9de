# toy car side profile ~120 mm long, two wheel arches, two windows
solid car {
    lower = Rectangle(center=(0, 15), width=120, height=24)
    cabin = Trapezoid(center=(-5, 37), bottom_width=70, top_width=46, height=20)
    Fixed(lower)
    Above(cabin, lower, gap=-1)
    hole arches {
        front = Circle(center=(35, 3), radius=13)
        rear = Circle(center=(-35, 3), radius=13)
    }
    AlignBottom(arches, lower)
    hole windows {
        w1 = Rectangle(center=(-18, 37), width=18, height=12)
        w2 = Rectangle(center=(6, 37), width=18, height=12)
    }
    AlignCenterY(windows, cabin)
    AlignCenterX(windows, cabin)
}
