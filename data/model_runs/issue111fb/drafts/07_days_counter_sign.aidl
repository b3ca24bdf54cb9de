# Request: a workshop "days without an accident" sign with two turning number wheels,
# all 3 mm ply, five layers screwed together. Front board 300 x 200 mm, R6 corners, with
# an engraved border 12 mm in, "THIS WORKSHOP HAS WORKED" (11 mm bold, filled) high up,
# "SAFELY FOR" (14 mm) under it, two windows 28 wide x 30 high, 40 mm apart (centres), 50 mm
# below the middle, and "DAYS WITHOUT AN ACCIDENT" (8 mm) under them. Behind it two wheels
# 128 mm across (tens left, ones right) turn on M5 countersunk bolts 72 mm either side of
# the middle on the windows' line, so each wheel's digits (0-9, 20 mm bold filled, on a
# 52 mm radius, 36 deg apart) pass its window upright; the wheels stick out 14 mm below the
# sign to be turned by thumb and have 24 scallops (R2.5) round the rim for grip. A spacer
# frame as thick as the wheels (10 mm sides, opening up to 4 mm above the wheels, open at
# the bottom) and a back board of the front's outline with two keyholes (9 mm head) 100 mm
# either side of the middle, 60 mm above it (12 mm clearance holes in the spacer behind
# them). Four M3 countersunk screws through all three boards, 5 mm in from the sides and
# 8 mm from top and bottom.

import "std/fasteners.aidl"
import "std/plates.aidl"

thickness 3 mm
t = 3 mm

board_w = 300 mm
board_h = 200 mm
win_y = -50 mm
wheel_x = 72 mm
digit_r = 52 mm
wheel_r = 64 mm
screws = [[-145, 92], [145, 92], [-145, -92], [145, -92]]

def wheel(x0=0 mm, y0=0 mm, window=0 deg) -> solid {
    disc = Circle(center=(x0, y0), radius=wheel_r)
    hole pivot { c = Circle(center=(x0, y0), diameter=5.5) }
    hole knurl { n = Circle(center=(x0 + wheel_r, y0), radius=2.5) }
    scallops = CircularPattern(knurl, 24, disc.center)
    drawing digits {
        for k in range(10) {
            d = Text(str(k), position=(x0 + digit_r * cos(window - k * 36 deg),
                                       y0 + digit_r * sin(window - k * 36 deg)),
                     size=20, font="sans:Bold", fill=true, valign="middle",
                     rotation=-k * 36 deg)
        }
    }
}

assembly sign {
    solid front {
        board = RoundedRectangle(center=(0, 0), width=board_w, height=board_h, corner_radius=6)
        hole windows {
            w_tens = Rectangle(center=(-20, win_y), width=28, height=30)
            w_ones = Rectangle(center=(20, win_y), width=28, height=30)
        }
        piv_l = clearance_hole(size=5, cx=-wheel_x, cy=win_y)
        piv_r = clearance_hole(size=5, cx=wheel_x, cy=win_y)
        Countersink([piv_l, piv_r], diameter=10)
        for s in screws {
            fix = clearance_hole(size=3, cx=s[0], cy=s[1])
        }
        Countersink(fix, diameter=6.5)
        drawing words {
            border = RoundedRectangle(center=(0, 0), width=board_w - 24, height=board_h - 24,
                                      corner_radius=3)
            l1 = Text("THIS WORKSHOP HAS WORKED", position=(0, 60), size=11, font="sans:Bold",
                      fill=true, valign="middle")
            l2 = Text("SAFELY FOR", position=(0, 25), size=14, font="sans:Bold", fill=true,
                      valign="middle")
            l3 = Text("DAYS WITHOUT AN ACCIDENT", position=(0, -80), size=8, font="sans:Bold",
                      fill=true, valign="middle")
        }
    }

    tens = wheel(x0=-wheel_x, y0=win_y, window=0 deg)
    ones = wheel(x0=wheel_x, y0=win_y, window=180 deg)

    solid spacer {
        frame = RoundedRectangle(center=(0, 0), width=board_w, height=board_h, corner_radius=6)
        hole opening {
            o = Rectangle(bottom_left=(-board_w / 2 + 10, -board_h / 2 - 10), width=board_w - 20,
                          height=board_h / 2 + 10 + win_y + wheel_r + 4)
        }
        hole heads {
            hl = Circle(center=(-100, 60), diameter=12)
            hr = Circle(center=(100, 60), diameter=12)
        }
        for s in screws {
            fix = clearance_hole(size=3, cx=s[0], cy=s[1])
        }
    }

    solid back {
        board = RoundedRectangle(center=(0, 0), width=board_w, height=board_h, corner_radius=6)
        k_l = keyhole(head=9, slot_width=4.5, length=10, cx=-100, cy=60)
        k_r = keyhole(head=9, slot_width=4.5, length=10, cx=100, cy=60)
        piv_l = clearance_hole(size=5, cx=-wheel_x, cy=win_y)
        piv_r = clearance_hole(size=5, cx=wheel_x, cy=win_y)
        for s in screws {
            fix = clearance_hole(size=3, cx=s[0], cy=s[1])
        }
    }

    # on the sheet
    RightOf(spacer, front, gap=6)
    AlignTop(spacer, front)
    Below(back, front, gap=20)
    AlignLeft(back, front)
    RightOf(tens, back, gap=6)
    AlignTop(tens, back)
    RightOf(ones, tens, gap=6)
    AlignTop(ones, tens)

    # in 3D: back board on the wall, spacer and wheels on it, front board on top
    Place(back, position=(0, 0, 0), face="front")
    Place(spacer, position=(0, -t, 0), face="front")
    Place(tens, position=(0, -t, 0), face="front")
    Place(ones, position=(0, -t, 0), face="front")
    Place(front, position=(0, -2 * t, 0), face="front")

    # the request's numbers
    assert front.board.width == 300 mm and front.board.height == 200 mm, "board 300 x 200"
    assert front.windows.w_tens.width == 28 mm and front.windows.w_tens.height == 30 mm, "windows 28 x 30"
    assert front.windows.w_ones.center.x - front.windows.w_tens.center.x == 40 mm, "40 apart"
    assert front.board.center.y - front.windows.w_tens.center.y == 50 mm, "50 below the middle"
    assert tens.disc.diameter == 128 mm, "wheels 128 across"
    assert front.piv_r.c.center.x - front.board.center.x == 72 mm, "bolts 72 out"
    assert front.windows.w_tens.center.x - tens.disc.center.x == 52 mm and
        ones.disc.center.x - front.windows.w_ones.center.x == 52 mm, "digits under the windows"
    assert front.board.bb.bottom - tens.disc.bb.bottom == 14 mm, "wheels stick out 14"
    assert len(tens.digits.d) == 10 and len(tens.scallops) == 24, "ten digits, 24 scallops"
    assert ones.disc.bb.left - tens.disc.bb.right >= 5 mm, "the wheels clear each other"
    assert spacer.opening.o.bb.left <= tens.disc.bb.left - 2 mm, "the spacer clears the wheels"
    assert spacer.opening.o.bb.top - tens.disc.bb.top == 4 mm, "opening 4 above the wheels"
    assert back.k_r.head_hole.center.x - back.k_l.head_hole.center.x == 200 mm, "keyholes 100 out"
    assert distance(front.words.l3, front.windows) >= 3 mm, "bottom line clear of the windows"
    assert distance(front.words.l2, front.windows) >= 3 mm, "SAFELY FOR clear of the windows"
    assert distance(front.words.border, front.fix[0]) >= 1 mm, "border clear of the screws"
}
