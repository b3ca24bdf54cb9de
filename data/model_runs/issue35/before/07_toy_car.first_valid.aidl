# A toy car body, side profile, about 120 mm long: a lower body with a cabin on
# top, two round wheel arches cut into the bottom edge and two side windows.

param length = 120 mm
param body_h = 28 mm
param arch_r = 13 mm
param wheelbase = 76 mm

solid car {
    # lower body with a sloped bonnet and boot
    lower = Polygon([(0, 0), (length, 0), (length, 18), (length - 10, body_h),
                     (10, body_h), (0, 20)])
    # the cabin sits on the lower body, set back a little from the middle
    cabin = Trapezoid(center=(length / 2 - 5, body_h + 10), bottom_width=70, top_width=44,
                      height=20)
    Above(cabin, lower, gap=-1)
    HorizontalDistance(lower.points[0], cabin.center, length / 2 - 5)
    Fixed(lower)

    hole arch_front {
        a = Circle(center=(length / 2 + wheelbase / 2, 0), radius=arch_r)
    }
    hole arch_rear {
        a = Circle(center=(length / 2 - wheelbase / 2, 0), radius=arch_r)
    }
    Coincident(arch_front.a.center, lower.edges[0])
    Coincident(arch_rear.a.center, lower.edges[0])
    HorizontalDistance(arch_rear.a.center, arch_front.a.center, wheelbase)
    AlignCenterX(self, lower)

    hole windows {
        front_w = Polygon([(0, 0), (24, 0), (24, 13), (6, 13)])
        rear_w = Polygon([(0, 0), (22, 0), (16, 13), (0, 13)])
        RightOf(front_w, rear_w, gap=4)
        AlignBottom(front_w, rear_w)
    }
    CenterInside(windows, cabin)
}
