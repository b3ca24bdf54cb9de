# Request (electronics): a 3 mm ply box for an Arduino Uno R3 (board 68.6 x 53.3 mm), 2 mm
# clear of every wall, 25 mm deep inside, finger-jointed. The floor has holes for M3
# standoffs (5 mm) under the Uno's four mounting holes at (14.0, 2.5), (15.3, 50.7),
# (66.1, 7.6) and (66.1, 35.5) mm from the board's bottom-left corner. The left wall has the
# USB-B opening (13 wide x 11.5 high, centred 38.1 mm up the board's left edge) and the DC
# barrel-jack opening (10 x 11.5, centred 7.6 mm up). No vents; instead the lid has a slot
# 42 x 5 mm over the digital header (its centre at (45.5, 50.8) on the board) for jumper
# wires, and "ARDUINO UNO" engraved 6 mm high, 8 mm below the lid's centre.

import "std/enclosures.aidl"

thickness 3 mm

board_w = 68.6 mm
board_h = 53.3 mm
uno_holes = [[14.0, 2.5], [15.3, 50.7], [66.1, 7.6], [66.1, 35.5]]
header_at = [45.5, 50.8]

assembly uno_box {
    box = board_enclosure(width=board_w, height=board_h, depth=25 mm, thickness=3 mm,
                          clearance=2 mm, holes=uno_holes, hole_d=3.2 mm, standoff=5 mm,
                          ports=[["left", 38.1, 13, 11.5], ["left", 7.6, 10, 11.5]],
                          vent="none")

    hole header {
        s = Slot(center=(0, 0), length=42, width=5)
    }
    # the board sits centred in the box: its centre is the lid's centre
    At(header.s.center, box.lid.bb.center, dx=header_at[0] - board_w / 2,
       dy=header_at[1] - board_h / 2)
    CutInto(header, box.lid)

    drawing label {
        name = Text("ARDUINO UNO", position=(0, 0), size=6, valign="middle")
    }
    At(label.name.position, box.lid.bb.center, dy=-8)
    CutInto(label, box.lid)

    assert box.length == 68.6 mm + 2 * 2 mm + 2 * 3 mm, "outer length: board + clearance + walls"
    assert box.tall == 25 mm + 2 * 3 mm, "25 mm deep inside"
    assert len(box.holes) == 4, "four standoff holes"
    assert header.s.length == 42 mm and header.s.width == 5 mm, "header slot 42 x 5"
}
