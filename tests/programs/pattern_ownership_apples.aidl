// Issue 14: a pattern of a structure written in the parent puts the copies beside the
// original (in `fruit`), not in the parent solid where they would merge into the table top.
units mm

solid table {
    top = Rectangle(center=(0, 0), width=100, height=100)
    drawing fruit {
        solid apple {
            body = Circle(center=(30, 0), radius=6)
        }
    }
    apples = CircularPattern(fruit.apple, 6, center=(0, 0))
}
