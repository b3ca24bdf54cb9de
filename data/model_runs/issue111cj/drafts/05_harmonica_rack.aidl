# Request: a desk rack for six 10-hole diatonic harmonicas (each 102 x 27 x 20 mm), stood on end
# in key order, 3 mm birch ply. A base 220 x 60 mm; two end sides 60 deep x 50 tall, top corners
# rounded r 10, finger-jointed to the base's ends; a deck 3 mm thick whose top is 40 mm above
# the base's underside, tabbed through both sides, with six 28 x 21 mm openings at a 34 mm
# pitch, centred along the deck, their centres 6 mm behind the deck's middle. In front of each
# opening its key engraved filled, 8 mm bold: C D E F G A (left to right). "HARPS" engraved
# on the outside of the right side, 8 mm.

units mm
thickness 3 mm
import "std/joints.aidl"

t = 3 mm
L = 220 mm
D = 60 mm
keys = ["C", "D", "E", "F", "G", "A"]
pitch = 34 mm
deck_top = 40 mm

def end_side(label="") -> solid {
    body = RoundedRectangle(center=(0, 25), width=D, height=50, corner_radii=[10, 10, 0, 0])
    foot = finger_edge(length=D, thickness=t, finger=10 mm, start="gap", rotation=180 deg,
                       cx=0, cy=0)
    deck_slots = tab_and_slot(part="slot", length=D, thickness=t, tabs=2, tab=15 mm, screw=0,
                              cx=0, cy=deck_top - t / 2)
    if label != "" {
        drawing name {
            word = Text(label, position=(0, 22), size=8, valign="middle")
        }
    }
}

assembly rack {
    solid base {
        board = Rectangle(center=(0, 0), width=L, height=D)
        left_end = finger_edge(length=D, thickness=t, finger=10 mm, start="tab",
                               rotation=90 deg, cx=-L / 2, cy=0)
        right_end = finger_edge(length=D, thickness=t, finger=10 mm, start="tab",
                                rotation=-90 deg, cx=L / 2, cy=0)
    }
    left = end_side()
    right = end_side(label="HARPS")
    solid deck {
        board = Rectangle(center=(0, 0), width=L, height=D)
        to_left = tab_and_slot(part="tab", length=D, thickness=t, tabs=2, tab=15 mm, screw=0,
                               rotation=90 deg, cx=-L / 2, cy=0)
        to_right = tab_and_slot(part="tab", length=D, thickness=t, tabs=2, tab=15 mm, screw=0,
                                rotation=-90 deg, cx=L / 2, cy=0)
        hole bay {
            r = Rectangle(center=(-2.5 * pitch, 6), width=28, height=21)
        }
        bays = LinearPattern(bay, 6, (pitch, 0))
        drawing keys_text {
            for i in range(6) {
                k = Text(keys[i], position=((i - 2.5) * pitch, -17), size=8, font="sans:Bold",
                         valign="middle", fill=true)
            }
        }
    }

    # flat on the sheet
    Above(deck, base, gap=10)
    AlignLeft(deck, base)
    RightOf(left, base, gap=10)
    AlignBottom(left, base)
    Above(right, left, gap=10)
    AlignLeft(right, left)

    # in 3D: x along the rack, y from front (-) to back, z up
    Place(base, position=(0, 0, 0))
    Place(left, rotation=(90 deg, 0, 90 deg), position=(-L / 2, 0, 0))
    Place(right, rotation=(90 deg, 0, 90 deg), position=(L / 2 - t, 0, 0))
    Place(deck, position=(0, 0, deck_top - t))

    assert base.board.width == 220 mm and base.board.height == 60 mm
    assert left.body.width == 60 mm and left.body.height == 50 mm
    assert len(deck.bays) == 6
    assert deck.bays[1].r.center.x - deck.bays[0].r.center.x == 34 mm
    assert deck.bays[0].r.width == 28 mm and deck.bays[0].r.height == 21 mm
    assert deck.bays[0].r.center.y - deck.board.center.y == 6 mm
    assert abs((deck.bays[0].r.center.x + deck.bays[5].r.center.x) / 2 - deck.board.center.x) < 0.001 mm
    assert left.deck_slots.slot[0].bb.top - left.body.bb.bottom == 40 mm
    assert len(deck.keys_text.k) == 6
}
