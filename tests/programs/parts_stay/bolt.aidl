# Issue 73: a bolt hole written at (20, 20) placed 10 mm in from the plate's top-right
# corner: the plate stays at (0, 0) and the bolt goes to (30, 15) (before: the bolt kept
# (20, 20) and the plate moved to (-10, 5)).
solid plate {
    body = Rectangle(center=(0, 0), width=80, height=50)
    hole bolt { c = Circle(center=(20, 20), diameter=6) }
    At(bolt.c.center, body.top_right, dx=-10, dy=-10)
}
