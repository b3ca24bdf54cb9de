# Request: a 3 mm acrylic finger-jointed case for my LCR-T4 component tester. Inside it holds
# a 105 x 60 mm floor area: the tester board (73 x 60, four M3 holes at (3.5, 3.5),
# (69.5, 3.5), (3.5, 56.5), (69.5, 56.5) from its bottom-left corner) on the left and a bay
# for the 9 V battery (48.5 x 26.5 x 17.5) on the right. 2 mm clearance all round, 20 mm
# inside depth, 5 mm standoffs. In the lid (positions from the board's bottom-left corner):
# the LCD window 42 x 28 centred at (46, 40); the ZIF socket opening 44 x 16 centred at
# (28, 12); a 12 mm hole for the TEST button at (64, 12). A slot for the slide power switch
# in the right wall, 12 x 6, centred 30 mm up the board edge. Engraved on the lid: "TEST"
# under the button, "1 2 3" over the ZIF opening, "LCR-T4" over the LCD window, and
# "9V" over the battery bay, centred at (89, 30).

import "std/enclosures.aidl"

thickness 3 mm

INNER_W = 105 mm
INNER_H = 60 mm

assembly tester {
    box = board_enclosure(width=INNER_W, height=INNER_H, depth=20 mm, thickness=3 mm,
                          clearance=2 mm,
                          holes=[[3.5, 3.5], [69.5, 3.5], [3.5, 56.5], [69.5, 56.5]],
                          hole_d=3.2 mm, standoff=5 mm,
                          ports=[["right", 30, 12, 6]], vent="none", finger=10 mm)

    # lid openings, drawn in board coordinates (origin: the board's bottom-left corner)
    hole lid_cuts {
        mid = Point(INNER_W / 2, INNER_H / 2, construction=true)
        lcd = Rectangle(center=(46, 40), width=42, height=28)
        zif = Rectangle(center=(28, 12), width=44, height=16)
        button = Circle(center=(64, 12), diameter=12)
        Rigid(self)
    }
    Coincident(lid_cuts.mid, box.lid.bb.center)
    CutInto(lid_cuts, box.lid)

    drawing lid_marks {
        mid = Point(INNER_W / 2, INNER_H / 2, construction=true)
        test = Text("TEST", position=(64, 2.5), size=3.5, valign="middle")
        pins = Text("1 2 3", position=(28, 23), size=3.5, valign="middle")
        model = Text("LCR-T4", position=(46, 57), size=3.5, valign="middle")
        batt = Text("9V", position=(89, 30), size=8, font="sans:Bold", valign="middle", fill=true)
        Rigid(self)
    }
    Coincident(lid_marks.mid, box.lid.bb.center)
    CutInto(lid_marks, box.lid)

    assert box.length == 105 mm + 2 * 2 mm + 2 * 3 mm, "outer length"
    assert box.wide == 60 mm + 2 * 2 mm + 2 * 3 mm, "outer width"
    assert lid_cuts.lcd.width == 42 mm and lid_cuts.lcd.height == 28 mm, "LCD window"
    assert lid_cuts.button.center.x - lid_cuts.lcd.center.x == 64 mm - 46 mm, "button vs LCD"
    # the battery bay lies right of the board, under the "9V"
    assert lid_marks.batt.position.x - lid_marks.mid.x == 89 mm - 105 mm / 2, "9V over the bay"
    assert 73 mm + 26.5 mm <= 105 mm, "the battery fits beside the board"
    assert distance(lid_marks.test, lid_cuts.button) >= 1 mm, "TEST clear of the button"
    assert distance(lid_marks.pins, lid_cuts.zif) >= 1 mm, "pins label clear of the ZIF"
    assert distance(lid_marks.model, lid_cuts.lcd) >= 1 mm, "model label clear of the LCD"
}
