# A rectangular plate 120.65 x 80.26 mm, 6.35 mm thick, with four 5.5 mm holes
# whose centres are 10.0 mm in from the long sides and 8.0 mm in from the short sides.
thickness 6.35 mm

solid plate {
    body = Rectangle(center=(0, 0), width=120.65, height=80.26)
    Fixed(body)
    hole h { c = Circle(center=(0, 0), diameter=5.5) }
    # inset (dx, dy): 8.0 from the short (left/right) sides, 10.0 from the long (top/bottom) sides
    CornerPattern(h, body, (8.0, 10.0))
}
