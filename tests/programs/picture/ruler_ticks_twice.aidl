# A 10 cm ruler drawn with two loops: a tick every millimetre and a longer one
# every centimetre, at the same places: at each centimetre the short tick lies
# under the long one and is burnt twice (issue 84).
solid ruler {
    bar = Rectangle(center=(60, 15), width=120, height=30)
    drawing mm {
        for i in range(101) {
            tick = Line((10 + i * 1 mm, 30), (10 + i * 1 mm, 26))
        }
    }
    drawing cm {
        for k in range(11) {
            tick = Line((10 + k * 10 mm, 30), (10 + k * 10 mm, 22))
        }
    }
}
