# A headphone hook: an L-shaped bracket with two mounting holes.
solid hook {
    back = Rectangle(bottom_left=(0, 0), width=10, height=80)
    arm = Rectangle(bottom_left=(0, 0), width=60, height=10)
    lip = Rectangle(bottom_left=(50, 0), width=10, height=20)
    hole m1 { c = Circle(center=(5, 60), diameter=4) }
    hole m2 { c = Circle(center=(5, 30), diameter=4) }
    Fillet(3)
}
