# Request (science): Napier's bones for the maths club, 3 mm ply. Ten rods 20 x 200 mm, one for each
# digit 0-9: the digit engraved 10 mm high in the top square, then nine 20 mm squares, each cut by an
# engraved diagonal (bottom left to top right), holding the digit times 1..9: tens above the diagonal
# (left), units below it (right), no tens digit when the product is under 10. A tray: a base and a
# glued frame, both 236 x 241 mm; the frame's window 201 x 201 mm holds the ten rods side by side
# (0.5 mm play each side), 25 mm strip on the left with the index 1-9 engraved level with the rods'
# squares, 10 mm strip on the right, 20 mm at top and bottom, a 20 mm thumb notch at the window's top.

thickness 3 mm

def rod(d=0) -> solid {
    body = Rectangle(bottom_left=(0, 0), width=20, height=200)
    drawing marks {
        head = Text(str(d), position=(10, 185), size=10)
        for k in range(1, 10) {
            y0 = 180 - 20 * k
            sep = Line((0, y0 + 20), (20, y0 + 20))
            diag = Line((0, y0), (20, y0 + 20))
            u = Text(str((d * k) % 10), position=(14.5, y0 + 3), size=6)
            if d * k >= 10 {
                tens = Text(str(d * k // 10), position=(5.5, y0 + 11), size=6)
            }
        }
    }
}

assembly napier {
    solid base {
        plate = Rectangle(center=(0, 0), width=236, height=241)
    }
    solid frame {
        plate = Rectangle(center=(0, 0), width=236, height=241)
        hole window { w = Rectangle(bottom_left=(-93, -100.5), width=201, height=201) }
        hole notch { c = Circle(center=(7.5, 100.5), diameter=20) }
        # FIX after the first valid program: the notch is meant to open into the window (W0508)
        AllowOverlap(window, notch)
        drawing index {
            for k in range(1, 10) {
                n = Text(str(k), position=(-105.5, 90 - 20 * k), size=8, valign="middle")
            }
        }
    }
    for i in range(10) {
        rods = rod(d=i)
    }

    # on the sheet
    RightOf(frame, base, gap=6)
    AlignTop(frame, base)
    Below(rods[0], base, gap=6)
    AlignLeft(rods[0], base)
    for i in range(1, 10) {
        RightOf(rods[i], rods[i - 1], gap=4)
        AlignTop(rods[i], rods[0])
    }

    # assembled: the rods lie in the frame's window on the base
    Place(base, position=(0, 0, 0))
    Place(frame, position=(0, 0, 3 mm))
    for i in range(10) {
        Place(rods[i], position=(-92.5 mm + 20 mm * i, -100 mm, 3 mm))
    }

    # the request's numbers
    assert len(rods) == 10, "ten rods"
    assert rods[3].body.bb.width == 20 mm and rods[3].body.bb.height == 200 mm, "rods 20 x 200"
    assert rods[7].marks.head.text == "7", "rod 7"
    assert rods[7].marks.u[7].text == "6" and rods[7].marks.u[0].text == "7", "7 x 8 = 56, 7 x 1 = 7"
    assert rods[9].marks.u[8].text == "1", "9 x 9 = 81"
    # rod 1 has no tens at all: its `tens` is never made (E0102), so only rod 9 is counted
    assert len(rods[9].marks.tens) == 8, "tens only from 10: 9 x 2 .. 9 x 9"
    assert rods[0].marks.head.size == 10 mm, "digit 10 mm high"
    assert base.plate.bb.width == 236 mm and base.plate.bb.height == 241 mm, "base 236 x 241"
    assert frame.window.w.bb.width == 201 mm and frame.window.w.bb.height == 201 mm, "window 201 x 201"
    assert frame.window.w.bb.left - frame.plate.bb.left == 25 mm, "25 mm left strip"
    assert frame.plate.bb.right - frame.window.w.bb.right == 10 mm, "10 mm right strip"
    assert frame.plate.bb.top - frame.window.w.bb.top == 20 mm, "20 mm top strip"
    assert frame.window.w.bb.bottom - frame.plate.bb.bottom == 20 mm, "20 mm bottom strip"
    assert 10 * rods[0].body.bb.width + 1 mm == frame.window.w.bb.width, "0.5 mm play each side"
    assert frame.notch.c.diameter == 20 mm, "20 mm thumb notch"
    assert len(frame.index.n) == 9, "index 1-9"
}
