# Request: a BIOHAZARD door sign for the school's microbiology prep room, two layers of
# 3 mm acrylic. A yellow backer 200 x 280 with R10 corners and four 5.5 mm holes for
# stand-off screws, 20 in from the corners. Glued on it, cut from black: a border frame
# 6 mm wide, 6 mm in from the edge; the biohazard symbol (unit A = 3 mm: three arms, each a
# circle of 15A whose centre is 11A from the symbol's centre, hollowed by a circle of 10.5A
# whose centre is 15A out; a central hole of 3A joined to each hollow by a 1A slit; a ring
# 3A wide from 11A to 14A), its centre 30 above the sign's middle, one arm up; and the word
# BIOHAZARD (20 mm caps, bold) standing on a 4 mm rail, its baseline 80 below the middle.

import "std/fasteners.aidl"

units mm
thickness 3 mm

A = 3 mm
sym_y = 30 mm
word_y = -80 mm
def arm(i) = 90 deg + i * 120 deg
def pc(r, a) = (r * cos(a), sym_y + r * sin(a))

assembly sign {
    solid backer {
        plate = RoundedRectangle(center=(0, 0), width=200, height=280, corner_radius=10)
        screw = clearance_hole(size=5)
        screws = CornerPattern(screw, plate, inset=20)
        assert screw.c.diameter == 5.5 mm, "5.5 mm stand-off holes"
        assert screws[2].c.center.x - screws[0].c.center.x == 160 mm and
            screws[2].c.center.y - screws[0].c.center.y == 240 mm, "holes 20 in from the corners"
    }

    solid frame {
        band = Shell(RoundedRectangle(center=(0, 0), width=176, height=256, corner_radius=2,
                                      construction=true), 6)
        assert band.bb.width == 188 mm and band.bb.height == 268 mm, "frame 6 in from the edge"
    }

    solid symbol {
        solid arms {
            for i in range(3) {
                c = Circle(center=pc(11 * A, arm(i)), radius=15 * A)
            }
            hole hollows {
                for i in range(3) {
                    h = Circle(center=pc(15 * A, arm(i)), radius=10.5 * A)
                }
            }
            hole core {
                c = Circle(center=pc(0, 0 deg), radius=3 * A)
                for i in range(3) {
                    s = Rectangle(start=pc(0, 0 deg), end=pc(5 * A, arm(i)), width=1 * A)
                }
                AllowOverlap(s)
            }
            # the slits join the core to each hollow: one opening, as meant
            AllowOverlap(hollows, core)
        }
        solid ring {
            band = Shell(Circle(center=pc(0, 0 deg), radius=11 * A, construction=true), 3 * A)
        }
        assert arms.c[0].radius == 45 mm, "arms 15A"
        assert arms.hollows.h[0].center.y - arms.c[0].center.y == 4 * A, "hollow 4A further out"
    }

    solid word {
        w = Text("BIOHAZARD", position=(0, word_y), size=20, font="sans:Bold")
        rail = Rectangle(center=(w.center.x, word_y - 1 mm), width=w.bb.width, height=4)
        assert w.bb.width <= 176 mm - 8 mm, "word inside the frame"
    }

    # flat on the sheet: the black pieces beside the backer
    RightOf(frame, backer, gap=8)
    AlignTop(frame, backer)
    RightOf(symbol, frame, gap=8)
    AlignTop(symbol, frame)
    Below(word, symbol, gap=8)
    AlignLeft(word, symbol)

    # assembled: the backer on the door, the black pieces on its face
    Place(backer, position=(0, 0, 1500), face="front", up="up")
    Place(frame, position=(0, -3, 1500), face="front", up="up")
    Place(symbol, position=(0, -3, 1500), face="front", up="up")
    Place(word, position=(0, -3, 1500), face="front", up="up")

    assert symbol.bb.width <= 176 mm - 10 mm, "symbol inside the frame"
    assert symbol.bb.top <= 128 mm - 5 mm, "symbol under the frame's top"
    assert symbol.bb.bottom - word.bb.top >= 10 mm, "symbol clear of the word"
    assert word.bb.bottom >= -128 mm + 5 mm, "word above the frame's bottom"
    assert symbol.ring.band.center.y == 30 mm, "symbol 30 above the middle"
}
