# expect: E0304 2:5
x = [[i for i in range(10000)] for j in range(10000)]
solid s { c = Circle((0, 0), 1) }
