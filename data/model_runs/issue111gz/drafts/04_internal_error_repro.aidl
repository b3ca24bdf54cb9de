# After part 04's first valid program: the smallest program found that gives the internal error
# "TypeError: _as_written() takes 2 positional arguments but 3 were given" instead of E0405:
# a FAILING assert that reads the box of a hole placed by an equation. (The same assert on a
# hole nobody moves gives E0405 normally.)
solid p {
    body = Rectangle(center=(0, 0), width=60, height=60)
    hole a { c = Circle(center=(0, -10), radius=3) }
    hole b { c = Circle(center=(0, 10), radius=3) }
    b.bb.bottom == a.bb.top + 10 mm
    assert body.bb.top - b.bb.top >= 50 mm, "b well inside"
}
