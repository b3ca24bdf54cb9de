# Engravings that cross as meant: a target's rings with a crosshair through
# them, a tic-tac-toe grid, a dial's finger stop across its rim, a border
# drawn to its inner line (no warning).
solid plate {
    body = Rectangle(center=(0, 0), width=200, height=100)
    drawing target {
        for k in range(3) {
            ring = Circle(center=(-60, 0), radius=10 + k * 10)
        }
        across = Line((-95, 0), (-25, 0))
        down = Line((-60, -40), (-60, 40))
    }
    drawing board {
        for k in range(2) {
            col = Line((10 + k * 20, -30), (10 + k * 20, 30))
            row = Line((-10, -10 + k * 20), (50, -10 + k * 20))
        }
    }
    drawing dial {
        rim = Circle(center=(75, 0), radius=15)
        stop = Line((75 + 12 * cos(-30 deg), 12 * sin(-30 deg)), (75 + 18 * cos(-30 deg), 18 * sin(-30 deg)))
    }
    drawing frame {
        edge = Rectangle(center=(0, 0), width=190, height=90)
        for k in range(5) {
            notch = Line((-80 + k * 40, 45), (-80 + k * 40, 41))
        }
    }
}
