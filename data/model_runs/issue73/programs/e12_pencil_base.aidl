# A pencil holder base: a disc with a ring of pencil holes.
solid base {
    disc = Circle(center=(0, 0), diameter=100)
    hole pencil { c = Circle(center=(35, 0), diameter=9) }
    CircularPattern(pencil, 10, disc.center)
    hole mid { c = Circle(center=(0, 0), diameter=30) }
}
