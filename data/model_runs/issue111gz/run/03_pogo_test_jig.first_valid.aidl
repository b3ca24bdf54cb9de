# Request (electronics): "A bed-of-nails test jig for my 50 x 30 mm sensor board, cut from 3 mm
# acrylic and stacked on four M3 standoffs. Four plates, each 110 x 80 mm with R4 corners and M3
# clearance holes 6 mm in from both edges; the board sits centred on the plates.
# - base: a 40 x 8 mm slot for the pogo wires, centred 12 mm in from the back (top) edge, and
#   'SENSOR TEST JIG' engraved along the front edge;
# - pin plate: six 1.7 mm holes for P75 pogo pins under the test pads, which are at (5, 5),
#   (5, 25), (20, 15), (35, 5), (45, 25) and (45, 5) mm from the board's bottom-left corner,
#   each labelled TP1..TP6 (engraved, 2.5 mm letters just above its pin);
# - carrier: a pocket cut through, the board's size plus 0.2 mm all round, with two R8 finger
#   notches on the middle of its top and bottom edges to lift the board out;
# - presser: slides down the standoffs onto the board, with a 30 x 15 mm window over the
#   board's centre (to see its LEDs) and 'PUSH' engraved beside it."

units mm
thickness 3 mm

import "std/plates.aidl"

plate_w = 110 mm
plate_h = 80 mm
board_w = 50 mm
board_h = 30 mm
pad_x = [5, 5, 20, 35, 45, 45]
pad_y = [5, 25, 15, 5, 25, 5]
bx = -board_w / 2      # board's bottom-left corner, plate centred at (0, 0)
by = -board_h / 2

def jig_plate() -> solid {
    p = mounting_plate(width=plate_w, height=plate_h, corner_radius=4 mm, screw=3, inset=6 mm)
}

assembly pogo_jig {
    solid base {
        plate = jig_plate()
        hole wires {
            s = Slot(center=(0, plate_h / 2 - 12), length=40, width=8)
        }
        drawing name {
            t = Text("SENSOR TEST JIG", position=(0, -plate_h / 2 + 10), size=5, valign="middle")
        }
        assert plate.p.body.bb.top - wires.s.center.y == 12 mm, "wire slot 12 in from the back"
        assert distance(name, plate.p.corner[0]) >= 2 mm, "name clear of the screw holes"
    }

    solid pin_plate {
        plate = jig_plate()
        hole pins {
            for i in range(6) {
                c = Circle(center=(bx + pad_x[i], by + pad_y[i]), diameter=1.7)
            }
        }
        drawing labels {
            for i in range(6) {
                t = Text(f"TP{i + 1}", position=(bx + pad_x[i], by + pad_y[i] + 2), size=2.5)
            }
        }
        assert len(pins.c) == 6, "six pogo pins"
        assert pins.c[0].center.x - plate.p.body.bb.left == 30 mm + 5 mm, "TP1 under its pad (x)"
        assert pins.c[0].center.y - plate.p.body.bb.bottom == 25 mm + 5 mm, "TP1 under its pad (y)"
        assert pins.c[4].center.x - plate.p.body.bb.left == 30 mm + 45 mm, "TP5 under its pad (x)"
        assert pins.c[4].center.y - plate.p.body.bb.bottom == 25 mm + 25 mm, "TP5 under its pad (y)"
        assert distance(labels, pins) >= 0.3 mm, "labels clear of the pin holes"
    }

    solid carrier {
        plate = jig_plate()
        hole pocket {
            r = Rectangle(center=(0, 0), width=board_w + 0.4, height=board_h + 0.4)
            top_notch = Circle(center=(0, board_h / 2 + 0.2), radius=8)
            bottom_notch = Circle(center=(0, -board_h / 2 - 0.2), radius=8)
        }
        assert pocket.r.bb.width == 50.4 mm and pocket.r.bb.height == 30.4 mm, "pocket board + 0.2"
    }

    solid presser {
        plate = jig_plate()
        hole window {
            r = Rectangle(center=(0, 0), width=30, height=15)
        }
        drawing push {
            t = Text("PUSH", position=(0, -20), size=6, valign="middle")
        }
        assert distance(push, window) >= 3 mm, "PUSH clear of the window"
    }

    RightOf(pin_plate, base, gap=8)
    AlignTop(pin_plate, base)
    Below(carrier, base, gap=8)
    AlignLeft(carrier, base)
    RightOf(presser, carrier, gap=8)
    AlignTop(presser, carrier)
}
