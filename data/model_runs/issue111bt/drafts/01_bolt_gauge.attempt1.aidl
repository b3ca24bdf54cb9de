# Request: a bolt and nut gauge for the workshop wall, cut from 3 mm plywood. A 190 x 70 mm
# plate with 6 mm rounded corners. Top row: close-fit clearance holes for M2, M3, M4, M5, M6,
# M8, M10 and M12 on a 20 mm pitch, centred 18 mm above the plate's middle, each with its size
# engraved above it (4 mm letters). Middle row: hexagonal nut pockets for M3, M4, M5, M6, M8 and
# M10 nuts on a 26 mm pitch, 5 mm below the middle, labelled underneath. Along the bottom edge an
# engraved 150 mm ruler for bolt lengths: a tick every 1 mm (3 mm long), every 5 mm (5 mm long),
# every 10 mm (7 mm long, numbered 0 to 150). Two 5 mm hanging holes, 8 mm in from the top
# corners.

units mm
thickness 3 mm
import "std/fasteners.aidl"

W = 190 mm
H = 70 mm
BOLTS = [2, 3, 4, 5, 6, 8, 10, 12]
NUTS = [3, 4, 5, 6, 8, 10]
BOLT_PITCH = 20 mm
NUT_PITCH = 26 mm
RULER = 150

solid gauge {
    plate = RoundedRectangle(center=(0, 0), width=W, height=H, corner_radius=6)
    Fixed(plate)

    for i in range(len(BOLTS)) {
        bolt = clearance_hole(size=BOLTS[i], fit="close",
                              cx=(i - (len(BOLTS) - 1) / 2) * BOLT_PITCH, cy=18)
    }
    for j in range(len(NUTS)) {
        nut = nut_trap(size=NUTS[j], cx=(j - (len(NUTS) - 1) / 2) * NUT_PITCH, cy=-5)
    }
    hole hang {
        left = Circle(center=(-W / 2 + 8, H / 2 - 8), diameter=5)
        right = Circle(center=(W / 2 - 8, H / 2 - 8), diameter=5)
    }

    drawing labels {
        for i in range(len(BOLTS)) {
            b = Text(f"M{BOLTS[i]}", position=((i - (len(BOLTS) - 1) / 2) * BOLT_PITCH, 27),
                     size=4)
        }
        for j in range(len(NUTS)) {
            n = Text(f"M{NUTS[j]}", position=((j - (len(NUTS) - 1) / 2) * NUT_PITCH, -21),
                     size=4)
        }
    }

    drawing ruler {
        for k in range(RULER + 1) {
            tick = Line(start=(-RULER / 2 + k, -H / 2),
                        end=(-RULER / 2 + k,
                             -H / 2 + (7 if k % 10 == 0 else (5 if k % 5 == 0 else 3))))
        }
        for m in range(0, RULER + 1, 10) {
            num = Text(str(m), position=(-RULER / 2 + m, -H / 2 + 8), size=2.5)
        }
    }

    # the request's own numbers
    assert plate.width == 190 mm and plate.height == 70 mm, "plate 190 x 70"
    assert len(bolt) == 8, "eight bolt holes M2..M12"
    assert len(nut) == 6, "six nut pockets M3..M10"
    assert bolt[1].c.center.x - bolt[0].c.center.x == 20 mm, "bolt holes on a 20 mm pitch"
    assert nut[1].hex.center.x - nut[0].hex.center.x == 26 mm, "nuts on a 26 mm pitch"
    assert bolt[0].c.center.y - plate.center.y == 18 mm, "bolt row 18 mm above the middle"
    assert plate.center.y - nut[0].hex.center.y == 5 mm, "nut row 5 mm below the middle"
    assert len(ruler.tick) == 151, "a tick every mm over 150 mm"
    assert ruler.tick[150].start.x - ruler.tick[0].start.x == 150 mm, "ruler 150 mm long"
    assert hang.left.diameter == 5 mm, "5 mm hanging holes"
    assert hang.left.center.x - plate.bb.left == 8 mm and plate.bb.top - hang.left.center.y == 8 mm,
        "hanging holes 8 mm in from the corners"
    # the biggest nut pocket must clear the bolt row and the labels under it
    assert bolt[7].c.bottom.y - nut[5].hex.bb.top >= 3 mm, "rows apart"
}
