# Request: a "BACK AT" shop-door sign with a settable clock, from 3 mm ply. A 200 x 280 mm
# board, 12 mm rounded corners, hung on a cord through two 5 mm holes 80 mm either side of
# the middle, 15 mm below the top. "BACK AT" engraved filled in bold sans, 24 mm high, centred
# 105 mm above the board's centre. Below it a clock face centred 5 mm below the board's
# centre: a filled 2 mm ring engraved at 82 mm radius, the hours 1-12 in filled bold sans,
# 11 mm high, on a 64 mm radius, a filled tick (6 x 2.5 mm) at each hour just inside the ring,
# a 5 mm hole in the middle for a Chicago screw. "SORRY WE MISSED YOU" engraved 9 mm high
# 115 mm below the centre. Two hands of 3 mm ply turning on the screw (5.2 mm holes): an hour
# hand 45 mm long to its 3 mm round tip from a 9 mm round boss, a minute hand 65 mm long to a
# 2 mm tip from a 7 mm boss with a 12 mm tail; a 14 mm washer between the hands. Shown set
# to 10:10.

import "std/shapes.aidl"

thickness 3 mm

CLOCK = (0, -5)
RING_R = 82 mm
NUM_R = 64 mm

def hand(length=45 mm, boss=9 mm, tip=3 mm, tail=0 mm) -> solid {
    # drawn pointing at 12 o'clock, the pivot at (0, 0)
    b = Circle(center=(0, 0), radius=boss)
    t = Circle(center=(0, length), radius=tip)
    if tail > 0 mm {
        k = Circle(center=(0, -tail), radius=tip + 2 mm)
        blade = Hull(b, t, k)
    } else {
        blade = Hull(b, t)
    }
    hole pivot { c = Circle(center=(0, 0), diameter=5.2) }
}

assembly sign {
    solid board {
        body = RoundedRectangle(center=(0, 0), width=200, height=280, corner_radius=12)
        hole cord {
            a = Circle(center=(-80, 140 - 15), diameter=5)
            b = Circle(center=(80, 140 - 15), diameter=5)
        }
        hole pivot { c = Circle(center=CLOCK, diameter=5) }
        drawing title {
            t = Text("BACK AT", position=(0, 105), size=24, font="sans:Bold", valign="middle",
                     fill=true)
        }
        drawing face {
            rim = Circle(center=CLOCK, radius=RING_R - 1 mm, construction=true)
            ring = Shell(rim, 2, fill=true)
            for h in range(1, 13) {
                n = Text(str(h), position=polar(CLOCK, NUM_R, 90 deg - h * 30 deg), size=11,
                         font="sans:Bold", valign="middle", fill=true)
                tick = Stroke(Line(polar(CLOCK, RING_R - 4 mm, 90 deg - h * 30 deg),
                                   polar(CLOCK, RING_R - 10 mm, 90 deg - h * 30 deg)),
                              width=2.5, cap="flat", fill=true)
            }
        }
        drawing footer {
            t = Text("SORRY WE MISSED YOU", position=(0, -115), size=9, valign="middle")
        }
    }

    hour = hand(length=45 mm, boss=9 mm, tip=3 mm)
    minute = hand(length=65 mm, boss=7 mm, tip=2 mm, tail=12 mm)
    spacer = washer(outer=14 mm, inner=5.2 mm)

    # 3D: hands stacked on the board's face at the clock's centre, set to 10:10
    # (hour hand 55 deg counter-clockwise from 12, minute hand 60 deg clockwise)
    Place(hour, rotation=(0, 0, 55 deg), position=(0, -5, 3))
    Place(spacer, position=(0, -5, 6))
    Place(minute, rotation=(0, 0, -60 deg), position=(0, -5, 9))

    # on the sheet
    RightOf(hour, board, gap=8)
    AlignTop(hour, board)
    RightOf(minute, hour, gap=8)
    AlignTop(minute, board)
    Below(spacer, hour, gap=8)
    AlignLeft(spacer, hour)

    # the request's numbers
    assert board.body.bb.width == 200 mm and board.body.bb.height == 280 mm, "board 200 x 280"
    assert board.cord.b.center.x - board.cord.a.center.x == 160 mm, "cord holes 80 either side"
    assert board.body.bb.top - board.cord.a.center.y == 15 mm, "cord holes 15 below the top"
    assert len(board.face.n) == 12, "twelve hours"
    assert hour.t.center.y - hour.b.center.y == 45 mm, "hour hand 45"
    assert minute.t.center.y - minute.b.center.y == 65 mm, "minute hand 65"
    assert minute.b.center.y - minute.k.center.y == 12 mm, "12 mm tail"
    assert spacer.outer == 14 mm, "14 mm washer"
    # the minute hand's tip stays inside the ring
    assert minute.length + minute.tip < RING_R - 1 mm, "hands inside the ring"
}
