# expect: E0112 2:5
k = (-8) ** 0.5
solid s { c = Circle((0, 0), 1) }
