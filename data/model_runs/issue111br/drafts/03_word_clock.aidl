# Request: the case of a word clock lit by WS2812B strip (60 LEDs per metre, so 16.667 mm
# pitch both ways), 230 x 230 mm, corners r6, a stack held by four M3 bolts 8 mm in from the
# corners. Front: 3 mm black acrylic with the classic 11 x 10 letter grid cut as stencil
# letters (bold, 9 mm tall), one letter over each LED. Behind it three 3 mm plywood light
# baffles, each with a 14 x 14 mm window over each LED. Behind those a 3 mm strip layer with a
# 12 mm channel along each row of LEDs, the rows joined at alternate ends so one strip
# snakes through (and a pocket for the hanging screw's head). Back: 3 mm plywood with a
# keyhole (9 mm head, 4.5 mm slot, 12 mm long, 18 mm below the top edge's middle), a 6 mm hole
# for the data cable at the start of the top row, and "WORD CLOCK - DATA IN" engraved by it.
# FIX after the first valid program: (1) the screw-head pocket ran out through the strip
# layer's top edge: the keyhole moves down to 24 mm below the top and the pocket stays inside;
# (2) the back plate's engraving faced into the stack: the back is drawn as seen from behind
# (cable hole on its right) and turned over in 3D, so the label is on the outside;
# (3) the unused template `layer_bolts` (W0117) is deleted.

units mm
thickness 3 mm

import "std/fasteners.aidl"
import "std/plates.aidl"

P = 1000 mm / 60        # LED pitch
SIDE = 230 mm
ROWS = ["ITLISASAMPM", "ACQUARTERDC", "TWENTYFIVEX", "HALFSTENFTO", "PASTERUNINE",
        "ONESIXTHREE", "FOURFIVETWO", "EIGHTELEVEN", "SEVENTWELVE", "TENSEOCLOCK"]
NR = 10
NC = 11
CH_W = NC * P + 8 mm    # a row channel's length
KEY_Y = SIDE / 2 - 24 mm

def cell_x(c) = (c - (NC - 1) / 2) * P
def cell_y(r) = ((NR - 1) / 2 - r) * P

def baffle() -> solid {
    plate = RoundedRectangle(center=(0, 0), width=SIDE, height=SIDE, corner_radius=6)
    bolt = clearance_hole(size=3, cx=-SIDE / 2 + 8 mm, cy=-SIDE / 2 + 8 mm)
    bolts = CornerPattern(bolt, plate, inset=8)
    hole window { w = Rectangle(center=(cell_x(0), cell_y(NR - 1)), width=14, height=14) }
    windows = GridPattern(window, NR, NC, (P, P))
}

assembly word_clock {
    solid face {
        plate = RoundedRectangle(center=(0, 0), width=SIDE, height=SIDE, corner_radius=6)
        bolt = clearance_hole(size=3, cx=-SIDE / 2 + 8 mm, cy=-SIDE / 2 + 8 mm)
        bolts = CornerPattern(bolt, plate, inset=8)
        hole letters {
            for r in range(NR) {
                for c in range(NC) {
                    ch = Text(ROWS[r][c], position=(cell_x(c), cell_y(r)), size=9,
                              font="sans:Bold", valign="middle", stencil=true)
                }
            }
        }
    }

    baffle1 = baffle()
    baffle2 = baffle()
    baffle3 = baffle()

    solid strips {
        plate = RoundedRectangle(center=(0, 0), width=SIDE, height=SIDE, corner_radius=6)
        bolt = clearance_hole(size=3, cx=-SIDE / 2 + 8 mm, cy=-SIDE / 2 + 8 mm)
        bolts = CornerPattern(bolt, plate, inset=8)
        hole channels {
            for r in range(NR) {
                row = Rectangle(center=(0, cell_y(r)), width=CH_W, height=12)
            }
            # row r joins row r + 1 at the right end when r is even, at the left when odd
            for r in range(NR - 1) {
                join = Rectangle(center=((1 if r % 2 == 0 else -1) * (CH_W / 2 - 5 mm),
                                         (cell_y(r) + cell_y(r + 1)) / 2),
                                 width=10, height=P)
            }
        }
        hole screw_head { s = Slot(center=(0, KEY_Y + 6 mm), length=25, width=13, rotation=90) }
    }

    # drawn as seen from behind (its engraved face is the outside)
    solid back {
        plate = RoundedRectangle(center=(0, 0), width=SIDE, height=SIDE, corner_radius=6)
        bolt = clearance_hole(size=3, cx=-SIDE / 2 + 8 mm, cy=-SIDE / 2 + 8 mm)
        bolts = CornerPattern(bolt, plate, inset=8)
        hang = keyhole(head=9 mm, slot_width=4.5 mm, length=12 mm, direction=90 deg,
                       cx=0, cy=KEY_Y)
        hole cable { c = Circle(center=(CH_W / 2 - 6 mm, cell_y(0)), diameter=6) }
        drawing note {
            t = Text("WORD CLOCK - DATA IN", position=(CH_W / 2, cell_y(0) + 10 mm), size=4,
                     anchor="end")
        }
    }

    # 3D: a stack, back at the bottom, the face on top
    Place(back, rotation=(0, 180 deg, 0), position=(0, 0, 3))
    Place(strips, position=(0, 0, 3))
    Place(baffle3, position=(0, 0, 6))
    Place(baffle2, position=(0, 0, 9))
    Place(baffle1, position=(0, 0, 12))
    Place(face, position=(0, 0, 15))

    # the sheet: two rows of three
    RightOf(baffle1, face, gap=5)
    RightOf(baffle2, baffle1, gap=5)
    Below(baffle3, face, gap=5)
    RightOf(strips, baffle3, gap=5)
    RightOf(back, strips, gap=5)
    AlignTop(baffle1, face)
    AlignTop(baffle2, face)
    AlignTop(strips, baffle3)
    AlignTop(back, baffle3)

    # the request's numbers
    assert len(ROWS) == 10 and len(ROWS[0]) == 11, "an 11 x 10 grid"
    assert len(face.letters.ch) == 10 and len(face.letters.ch[0]) == 11, "110 letters"
    assert face.plate.bb.width == 230 mm and face.plate.bb.height == 230 mm, "230 x 230"
    assert abs(face.letters.ch[0][1].position.x - face.letters.ch[0][0].position.x - 16.667 mm) < 0.01 mm,
        "letters on the LED pitch"
    assert abs(baffle1.windows[1].w.center.x - baffle1.windows[0].w.center.x - 16.667 mm) < 0.01 mm,
        "windows on the LED pitch"
    assert baffle1.window.w.bb.width == 14 mm, "14 mm windows"
    assert back.plate.bb.top - back.hang.head_hole.center.y == 24 mm, "keyhole 24 below the top"
    assert strips.plate.bb.top - strips.screw_head.s.bb.top >= 3 mm, "the pocket stays inside"
    assert strips.screw_head.s.bb.bottom - (strips.channels.row[0].bb.top) >= 3 mm,
        "a wall between the pocket and the top channel"
}
