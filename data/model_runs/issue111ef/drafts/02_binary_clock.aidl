# Request (electronics): a case for a desk binary clock (BCD, 5 mm LEDs), 3 mm plywood.
# - A finger-jointed box 160 wide, 50 deep, 100 tall (outer size), 10 mm fingers.
# - Front: 20 holes of 5.2 mm for 5 mm LEDs in six columns holding 2, 4, 3, 4, 3, 4 LEDs
#   from the bottom row up (tens and units of hours, minutes, seconds); the two columns of
#   a pair 16 mm apart, the pairs 44 mm apart (first column to first column), rows 14 mm
#   apart; the block of columns centred left-right, its bottom row 20 mm below the front's
#   centre.
# - Engraved on the front: the bit weights 8 4 2 1 left of the rows, H M S under the
#   pairs, BINARY CLOCK above the LEDs.
# - Lid: two 7 mm holes for the set buttons, 30 mm apart, centred on the lid.
# - Back: an 8 mm hole for the DC jack, centred, 20 mm above the bottom edge, and four
#   vent slots 60 x 4 mm, 10 mm apart, the top one 15 mm below the top edge.

import "std/joints.aidl"

thickness 3 mm

counts = [2, 4, 3, 4, 3, 4]
col_x = [-52, -36, -8, 8, 36, 52]
weights = ["1", "2", "4", "8"]

assembly clock {
    box = finger_box(length=160 mm, depth=50 mm, height=100 mm, thickness=3 mm, finger=10 mm)

    hole leds {
        for i in range(6) {
            for j in range(counts[i]) {
                c = Circle(center=(col_x[i], j * 14), diameter=5.2)
            }
        }
    }
    drawing labels {
        for k in range(4) {
            w = Text(weights[k], position=(-62, k * 14), size=5, anchor="end", valign="middle")
        }
        h = Text("H", position=(-44, -13), size=5, valign="middle")
        m = Text("M", position=(0, -13), size=5, valign="middle")
        s = Text("S", position=(44, -13), size=5, valign="middle")
        title = Text("BINARY CLOCK", position=(0, 58), size=6, valign="middle")
    }
    Rigid(leds, labels)
    AlignCenterX(leds, box.front)
    leds.c[0][0].center.y == box.front.bb.center_y - 20 mm
    CutInto(leds, box.front)
    CutInto(labels, box.front)

    hole buttons {
        b1 = Circle(center=(-15, 0), diameter=7)
        b2 = Circle(center=(15, 0), diameter=7)
    }
    CenterInside(buttons, box.lid)
    CutInto(buttons, box.lid)

    hole jack {
        c = Circle(center=(0, 0), diameter=8)
    }
    AlignCenterX(jack, box.back)
    jack.c.center.y == box.back.bb.bottom + 20 mm
    CutInto(jack, box.back)

    hole vents {
        for i in range(4) {
            v = Slot(center=(0, -i * 10), length=60, width=4)
        }
    }
    AlignCenterX(vents, box.back)
    vents.bb.top == box.back.bb.top - 15 mm
    CutInto(vents, box.back)

    assert box.front.bb.width == 160 mm and box.front.bb.height == 100 mm, "160 wide, 100 tall"
    assert box.left.bb.height == 50 mm, "50 deep"
    assert sum([len(leds.c[i]) for i in range(6)]) == 20, "20 LEDs"
    assert leds.c[1][0].center.x - leds.c[0][0].center.x == 16 mm, "pair columns 16 apart"
    assert leds.c[2][0].center.x - leds.c[0][0].center.x == 44 mm, "pairs 44 apart"
    assert leds.c[1][3].center.y - leds.c[1][2].center.y == 14 mm, "rows 14 apart"
    assert leds.c[0][0].diameter == 5.2 mm, "5.2 mm holes"
    assert buttons.b2.center.x - buttons.b1.center.x == 30 mm, "buttons 30 apart"
    assert jack.c.center.y - box.back.bb.bottom == 20 mm, "jack 20 above the bottom"
    assert labels.bb.left >= box.front.core.bb.left and labels.bb.top <= box.front.core.bb.top,
        "engraving clear of the finger joints"
}
