# A spray-paint stencil: HELLO cut out of a 200 x 70 mm sheet, the letters'
# islands (the O's middle) held by bridges so nothing falls out.
# Before issue 95 (no stencil Text): every letter built from rectangles and two
# arc slots, each stroke 6 mm wide, letters 36 mm tall.
units mm

solid stencil {
    sheet = RoundedRectangle(center=(0, 0), width=200, height=70, corner_radius=5)
    hole h {
        left = Rectangle(center=(-80, 0), width=6, height=36)
        right = Rectangle(center=(-60, 0), width=6, height=36)
        bar = Rectangle(center=(-70, 0), width=20, height=6)
    }
    hole e {
        spine = Rectangle(center=(-42, 0), width=6, height=36)
        top = Rectangle(center=(-33, 15), width=18, height=6)
        mid = Rectangle(center=(-34, 0), width=16, height=6)
        bottom = Rectangle(center=(-33, -15), width=18, height=6)
    }
    hole l1 {
        spine = Rectangle(center=(-12, 0), width=6, height=36)
        foot = Rectangle(center=(-3, -15), width=18, height=6)
    }
    hole l2 {
        spine = Rectangle(center=(18, 0), width=6, height=36)
        foot = Rectangle(center=(27, -15), width=18, height=6)
    }
    hole o {
        left = ArcSlot(center=(62, 0), radius=15, start_angle=100 deg, end_angle=260 deg, width=6)
        right = ArcSlot(center=(62, 0), radius=15, start_angle=-80 deg, end_angle=80 deg, width=6)
    }
    hole hang { c = Circle(center=(-90, 26), radius=3) }
}
