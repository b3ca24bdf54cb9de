# Request: a diddley bow (one-string slide guitar) from 6 mm ply, three parts.
# - Plank 600 x 60 mm. Scale length 500 mm: the nut stands 60 mm from the head end, the
#   bridge 500 mm past it, both glued in mortises (2 tabs 15 mm wide). A 10 mm hole for a
#   guitar tuning machine 25 mm from the head end, with its 2 mm locating-screw hole 12 mm
#   towards the nut; a 3 mm string-anchor hole 10 mm from the tail end. Engraved: a line at
#   each of the 12 fret positions (equal temperament: fret n at 500 - 500 / 2^(n/12) mm from
#   the nut), filled dots between frets at 3, 5, 7, 9 and two at 12, and "ONE STRING" between
#   the 12th fret and the bridge.
# - Nut: 60 x 15 mm (tabs included), a V notch 3 mm deep at the top centre for the string.
# - Bridge: trapezoid 60 mm at the foot, 40 mm at the top, 22 mm tall, same V notch, and a
#   30 mm arch cut out of its foot between the tabs (lighter, rings better).

import "std/joints.aidl"

thickness 6 mm

param t = 6 mm, min = 4 mm, max = 7 mm
param scale = 500 mm, min = 400 mm, max = 540 mm
nut_x = 60 mm
def fret(n) = scale - scale / 2 ** (n / 12)

assembly bow {
    solid plank {
        board = Rectangle(bottom_left=(0, -30), width=600, height=60)
        nut_slots = tab_and_slot(part="slot", length=60 mm, thickness=t, tabs=2, tab=15 mm,
                                 screw=0, rotation=90 deg, cx=nut_x, cy=0 mm)
        bridge_slots = tab_and_slot(part="slot", length=60 mm, thickness=t, tabs=2, tab=15 mm,
                                    screw=0, rotation=90 deg, cx=nut_x + scale, cy=0 mm)
        hole tuner { c = Circle(center=(25, 0), diameter=10) }
        hole tuner_pin { c = Circle(center=(37, 0), diameter=2) }
        hole anchor { c = Circle(center=(590, 0), diameter=3) }
        drawing frets {
            for n in range(1, 13) {
                f = Line((nut_x + fret(n), -26), (nut_x + fret(n), 26))
            }
            for n in [3, 5, 7, 9] {
                dot = Circle(center=(nut_x + (fret(n - 1) + fret(n)) / 2, 0), radius=3, fill=true)
            }
            d12a = Circle(center=(nut_x + (fret(11) + fret(12)) / 2, 12), radius=3, fill=true)
            d12b = Circle(center=(nut_x + (fret(11) + fret(12)) / 2, -12), radius=3, fill=true)
            words = Text("ONE STRING", position=(nut_x + (fret(12) + scale) / 2, 0), size=9,
                         valign="middle")
        }
        Fixed(board)
        Fixed(frets)
        assert board.width == 600 mm and board.height == 60 mm
        assert bridge_slots.bb.center_x - nut_slots.bb.center_x == 500 mm, "scale length"
        assert nut_slots.bb.center_x - board.bb.left == 60 mm
        assert len(frets.f) == 12
        assert frets.f[11].start.x - nut_slots.bb.center_x == 250 mm, "12th fret at half"
        assert tuner.c.center.x - board.bb.left == 25 mm
        assert tuner_pin.c.center.x - tuner.c.center.x == 12 mm
        assert board.bb.right - anchor.c.center.x == 10 mm
    }

    solid nut {
        body = Rectangle(center=(0, 7.5), width=60, height=15)
        feet = tab_and_slot(part="tab", length=60 mm, thickness=t, tabs=2, tab=15 mm, screw=0,
                            rotation=180 deg, cx=0 mm, cy=0 mm)
        hole notch { v = Polygon([(-2, 15.5), (0, 12), (2, 15.5)]) }
        Fixed(body)
        assert body.height == 15 mm
    }

    solid bridge {
        body = Trapezoid(center=(0, 11), bottom_width=60, top_width=40, height=22)
        feet = tab_and_slot(part="tab", length=60 mm, thickness=t, tabs=2, tab=15 mm, screw=0,
                            rotation=180 deg, cx=0 mm, cy=0 mm)
        hole notch { v = Polygon([(-2, 22.5), (0, 19), (2, 22.5)]) }
        # FIX after the first valid program: a 30 mm arch ate half of each 15 mm tab (the
        # tabs stand at +-15 mm, 15 wide, leaving 15 mm between them): 14 mm fits between
        hole arch { a = Circle(center=(0, 0), diameter=14) }
        assert arch.a.diameter <= feet.gap[1].bb.width, "the arch stays between the tabs"
        Fixed(body)
        assert body.height == 22 mm and body.bottom_width == 60 mm and body.top_width == 40 mm
    }

    Above(nut, plank, gap=10)
    AlignLeft(nut, plank)
    RightOf(bridge, nut, gap=10)
    AlignBottom(bridge, nut)

    Place(plank, position=(0, 0, 0), face="up")
    Place(nut, position=(nut_x - t / 2, 0, 0), face="right", up="up")
    Place(bridge, position=(nut_x + scale - t / 2, 0, 0), face="right", up="up")
}
