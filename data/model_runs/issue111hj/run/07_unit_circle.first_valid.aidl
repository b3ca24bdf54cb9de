# Request (science): a unit-circle teaching board for a maths classroom, 3 mm ply, and a
# pointer that turns on it.
# - board 300 x 300 mm, 10 mm corner radii, a 6 mm pivot hole in the middle; engraved: the
#   circle (120 mm radius = 1), x and y axes through the middle, 280 mm long; a 6 mm tick
#   across the circle every 15 deg (24); the degrees every 30 deg outside the circle
#   (0°, 30° ... 330°, 5 mm, their middles on a 132 mm radius) and the radians inside
#   (0, π/6 ... 11π/6, 5 mm, on a 104 mm radius); labels that would sit on an axis sit
#   beside it instead, 2 mm off; "cos θ" at the x axis's right end under it, "sin θ" at
#   the y axis's top end right of it; "THE UNIT CIRCLE" (6 mm) in the top left corner.
# - pointer: a 20 mm round boss with a 6 mm pivot hole, tapering to a point 125 mm from
#   the pivot; a centre line engraved from 14 to 110 mm.
thickness 3 mm

R = 120 mm
RAD = ["0", "π/6", "π/3", "π/2", "2π/3", "5π/6", "π", "7π/6", "4π/3", "3π/2", "5π/3",
       "11π/6"]

assembly unit_circle {
    solid board {
        body = RoundedRectangle(center=(0, 0), width=300, height=300, corner_radius=10)
        hole pivot {
            c = Circle(center=(0, 0), diameter=6)
        }
        drawing face {
            ring = Circle(center=(0, 0), radius=R)
            x_axis = Line((-140, 0), (140, 0))
            y_axis = Line((0, -140), (0, 140))
            for k in range(24) {
                tick = Line((117 * cos(k * 15 deg), 117 * sin(k * 15 deg)),
                            (123 * cos(k * 15 deg), 123 * sin(k * 15 deg)))
            }
            for i in range(12) {
                if i % 3 != 0 {
                    deg = Text(f"{i * 30}°", position=(132 * cos(i * 30 deg), 132 * sin(i * 30 deg)),
                               size=5, valign="middle")
                    rad = Text(RAD[i], position=(104 * cos(i * 30 deg), 104 * sin(i * 30 deg)),
                               size=5, valign="middle", font="sans", fill=true)
                } elif i == 0 {
                    deg = Text("0°", position=(132, 2), size=5, valign="bottom")
                    rad = Text(RAD[i], position=(104, 2), size=5, valign="bottom", font="sans",
                               fill=true)
                } elif i == 3 {
                    deg = Text("90°", position=(-2, 132), size=5, anchor="end", valign="middle")
                    rad = Text(RAD[i], position=(-2, 104), size=5, anchor="end", valign="middle",
                               font="sans", fill=true)
                } elif i == 6 {
                    deg = Text("180°", position=(-132, 2), size=5, valign="bottom")
                    rad = Text(RAD[i], position=(-104, 2), size=5, valign="bottom", font="sans",
                               fill=true)
                } else {
                    deg = Text("270°", position=(2, -132), size=5, anchor="start", valign="middle")
                    rad = Text(RAD[i], position=(2, -104), size=5, anchor="start", valign="middle",
                               font="sans", fill=true)
                }
            }
            cos_label = Text("cos θ", position=(140, -2), size=5, anchor="end", valign="top",
                             font="sans", fill=true)
            sin_label = Text("sin θ", position=(2, 140), size=5, anchor="start", valign="top",
                             font="sans", fill=true)
            title = Text("THE UNIT CIRCLE", position=(-140, 138), size=6, anchor="start")
        }
    }

    solid pointer {
        blade = Hull(Circle(center=(0, 0), diameter=20), Point(125, 0))
        hole pivot {
            c = Circle(center=(0, 0), diameter=6)
        }
        drawing mark {
            l = Line((14, 0), (110, 0))
        }
    }

    RightOf(pointer, board, gap=10)
    AlignCenterY(pointer, board)
    Place(pointer, on=board, position=(0, 0))

    assert board.body.width == 300 mm and board.body.height == 300 mm, "board 300 x 300"
    assert board.face.ring.radius == 120 mm, "unit circle 120 mm"
    assert board.face.x_axis.length == 280 mm and board.face.y_axis.length == 280 mm, "axes 280"
    assert len(board.face.tick) == 24, "a tick every 15 deg"
    assert len(board.face.deg) == 12 and len(board.face.rad) == 12, "12 labels each"
    assert board.face.tick[1].length == 6 mm, "ticks 6 mm"
    assert board.face.bb.left >= board.body.bb.left + 5 mm, "engraving inside the board"
    assert board.face.bb.top <= board.body.bb.top - 5 mm, "engraving inside the board"
    assert board.face.bb.right <= board.body.bb.right - 5 mm, "engraving inside the board"
    assert board.face.bb.bottom >= board.body.bb.bottom + 5 mm, "engraving inside the board"
    assert pointer.blade.bb.right - pointer.pivot.c.center.x == 125 mm, "point 125 from the pivot"
    assert pointer.pivot.c.diameter == board.pivot.c.diameter, "one pivot pin"
    # every label clear of the circle
    for i in range(12) {
        assert distance(board.face.deg[i], board.face.ring) >= 2 mm, "degrees clear of the circle"
        assert distance(board.face.rad[i], board.face.ring) >= 2 mm, "radians clear of the circle"
    }
}
