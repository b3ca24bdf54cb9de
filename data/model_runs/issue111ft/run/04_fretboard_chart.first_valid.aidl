# Request: a desk chart for learning the notes on a guitar neck, in 3 mm birch ply. A card
# 300 x 90 mm, corners R6, standing in two feet 80 x 25 mm (top corners R8) by cross
# halvings 12.5 mm deep, 100 mm either side of the middle. Engraved on it: six strings 11 mm
# apart in standard tuning, low E at the bottom as in tablature; a filled nut 3 mm wide;
# frets 1-12 at their true positions for a 520 mm scale (the 12th fret 260 mm from the
# nut); every note name (sharps, single-stroke 3.5 mm) in the middle of its fret space
# on its string, the string line broken round it, the open-string names left of the nut;
# filled 5 mm inlay dots at frets 3, 5, 7, 9 and a pair at 12; fret numbers under the
# low E; "STANDARD TUNING  E A D G B E" along the bottom.

import "std/joints.aidl"

t = 3 mm
thickness t

SCALE = 520 mm
NUT_X = -125 mm
NAMES = ["C", "C#", "D", "D#", "E", "F", "F#", "G", "G#", "A", "A#", "B"]
OPEN = [4, 9, 2, 7, 11, 4]          # E A D G B E, low E first
FRETS = 12
SLOT_X = 100 mm
FOOT_H = 25 mm

def fret_x(n) = NUT_X + SCALE * (1 - 2 ** (-n / 12))
def note_x(n) = NUT_X - 9 mm if n == 0 else (fret_x(n - 1) + fret_x(n)) / 2
def sy(s) = -17 mm + s * 11 mm
DOT_FRETS = [3, 5, 7, 9]

def foot() -> solid {
    body = RoundedRectangle(corner=(-40, 0), opposite=(40, FOOT_H), corner_radii=[8, 8, 0, 0])
    slot = cross_halving(depth=FOOT_H / 2, thickness=t, clearance=0.2, cx=0, cy=FOOT_H)
}

assembly fretboard_chart {
    solid card {
        body = RoundedRectangle(center=(0, 0), width=300, height=90, corner_radius=6)
        left_slot = cross_halving(depth=FOOT_H / 2, thickness=t, clearance=0.2, rotation=180,
                                  cx=-SLOT_X, cy=-45)
        right_slot = cross_halving(depth=FOOT_H / 2, thickness=t, clearance=0.2, rotation=180,
                                   cx=SLOT_X, cy=-45)

        drawing board {
            for s in range(6) {
                string = Line((NUT_X, sy(s)), (fret_x(FRETS), sy(s)))
            }
            for n in range(1, FRETS + 1) {
                fret = Line((fret_x(n), sy(0)), (fret_x(n), sy(5)))
            }
            # the string lines break round each fretted note name
            hole behind_notes {
                for s in range(6) {
                    for n in range(1, FRETS + 1) {
                        b = RoundedRectangle(center=(note_x(n), sy(s)), width=9, height=5,
                                             corner_radius=1.5)
                    }
                }
            }
        }
        drawing notes {
            for s in range(6) {
                for n in range(FRETS + 1) {
                    name = Text(NAMES[(OPEN[s] + n) % 12], position=(note_x(n), sy(s)),
                                size=3.5, valign="middle")
                }
            }
        }
        drawing inlays {
            nut = Rectangle(corner=(NUT_X - 1.5, sy(0) - 1), opposite=(NUT_X + 1.5, sy(5) + 1),
                            fill=true)
            for n in DOT_FRETS {
                dot = Circle(center=(note_x(n), (sy(2) + sy(3)) / 2), diameter=5, fill=true)
            }
            d12a = Circle(center=(note_x(12), (sy(1) + sy(2)) / 2), diameter=5, fill=true)
            d12b = Circle(center=(note_x(12), (sy(3) + sy(4)) / 2), diameter=5, fill=true)
        }
        drawing legend {
            for n in range(1, FRETS + 1) {
                num = Text(str(n), position=(note_x(n), sy(0) - 7), size=3, valign="middle")
            }
            title = Text("STANDARD TUNING  E A D G B E", position=(0, -36), size=4,
                         valign="middle")
        }
    }
    left_foot = foot()
    right_foot = foot()

    # flat on the sheet
    Below(left_foot, card, gap=10)
    AlignLeft(left_foot, card)
    RightOf(right_foot, left_foot, gap=10)
    AlignTop(right_foot, left_foot)

    # in 3D: the card upright on the desk, the feet across it
    Place(card, position=(0, t / 2, 45), face="front", up="up")
    Place(left_foot, position=(-SLOT_X - t / 2, 0, 0), face="left", up="up")
    Place(right_foot, position=(SLOT_X + t / 2, 0, 0), face="left", up="up")

    assert card.body.bb.width == 300 mm and card.body.bb.height == 90 mm, "card 300 x 90"
    assert fret_x(12) - NUT_X == 260 mm, "12th fret 260 mm from the nut"
    assert len(card.board.string) == 6 and len(card.board.fret) == 12, "6 strings, 12 frets"
    assert card.board.string[1].start.y - card.board.string[0].start.y == 11 mm,
        "strings 11 apart"
    assert card.notes.name[0][5].text == "A", "low E, 5th fret is A"
    assert card.notes.name[5][0].text == "E", "high e open"
    assert card.left_slot.depth + left_foot.slot.depth == left_foot.body.bb.height,
        "halvings meet: the card stands on the desk"
    assert left_foot.body.bb.width == 80 mm and left_foot.body.bb.height == 25 mm,
        "feet 80 x 25"
    assert card.right_slot.cut.bb.center_x - card.left_slot.cut.bb.center_x == 200 mm,
        "slots 100 either side"
    assert card.inlays.dot[0].diameter == 5 mm, "5 mm dots"
}
