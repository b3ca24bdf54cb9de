# Request: an anniversary gift, a "sound wave" plaque of a recorded "I love you", 3 mm ply
# front over a 3 mm red acrylic back that shows through the cut wave.
# - Front and back plates 240 x 120 (8 mm corners).
# - The wave: 41 bars 3 mm wide (round ends) at 5 mm pitch, centred on a line 10 mm above the
#   plate's centre, their heights taken from the recording's envelope (4 to 70 mm), cut
#   through the front.
# - "ANNA & TOM" engraved filled (bold, 9 mm) under the wave, and the date "14.02.2026"
#   (5 mm single-stroke) under the names.
# - Two feet 60 long x 25 tall, 80 mm either side of the centre, each with a 12 mm deep slot
#   6.2 mm wide (both plates plus 0.2 mm play) in which the plaque stands.

import "std/joints.aidl"

units mm
thickness 3 mm

T = 3 mm
W = 240 mm
H = 120 mm
AMP = [6, 10, 18, 30, 22, 14, 40, 58, 70, 52, 36, 20, 12, 26, 44, 62, 48, 30, 16, 8, 12, 24, 38,
       56, 66, 60, 42, 28, 18, 34, 50, 40, 26, 14, 20, 32, 24, 14, 10, 6, 4]
PITCH = 5 mm
WAVE_Y = 10 mm
FOOT_X = 80 mm
SLOT_DEPTH = 12 mm
FOOT_H = 25 mm

def foot() -> solid {
    body = RoundedRectangle(center=(0, FOOT_H / 2), width=60, height=FOOT_H, corner_radii=[6, 6, 0, 0])
    seat = cross_halving(depth=SLOT_DEPTH, thickness=2 * T, clearance=0.2 mm, cx=0 mm, cy=FOOT_H)
}

assembly plaque {
    solid front {
        body = RoundedRectangle(center=(0, 0), width=W, height=H, corner_radius=8)
        hole wave {
            for i in range(len(AMP)) {
                bar = Slot(center=((i - (len(AMP) - 1) / 2) * PITCH, WAVE_Y), length=AMP[i],
                           width=3, rotation=90 deg)
            }
        }
        drawing names {
            t = Text("ANNA & TOM", position=(0, -40), size=9, font="sans:Bold", valign="middle",
                     fill=true)
        }
        drawing date {
            t = Text("14.02.2026", position=(0, -53), size=5, valign="middle")
        }
    }

    solid back {
        body = RoundedRectangle(center=(0, 0), width=W, height=H, corner_radius=8)
    }

    foot_l = foot()
    foot_r = foot()

    # on the sheet
    Below(back, front, gap=8)
    AlignCenterX(back, front)
    RightOf(foot_l, front, gap=8)
    AlignTop(foot_l, front)
    RightOf(foot_r, front, gap=8)
    foot_r.bb.top == foot_l.bb.bottom - 8

    # assembled: the plaque standing in the feet, front face toward -y
    Place(front, rotation=(90 deg, 0, 0), position=(0, 0, FOOT_H - SLOT_DEPTH + H / 2))
    Place(back, rotation=(90 deg, 0, 0), position=(0, T, FOOT_H - SLOT_DEPTH + H / 2))
    Place(foot_l, rotation=(90 deg, 0, 90 deg), position=(-FOOT_X - T / 2, 0, 0))
    Place(foot_r, rotation=(90 deg, 0, 90 deg), position=(FOOT_X - T / 2, 0, 0))

    # the request's numbers
    assert front.body.bb.width == 240 mm and front.body.bb.height == 120 mm, "plates 240 x 120"
    assert len(front.wave.bar) == 41, "41 bars"
    assert front.wave.bar[1].center.x - front.wave.bar[0].center.x == 5 mm, "5 mm pitch"
    assert front.wave.bar[8].length == 70 mm and front.wave.bar[40].length == 4 mm, "bars 4 to 70 mm"
    assert front.wave.bar[0].width == 3 mm, "bars 3 mm wide"
    assert front.wave.bar[20].center.y - front.body.center.y == 10 mm, "wave 10 mm above the centre"
    assert abs(front.wave.bar[20].center.x - front.body.center.x) < 0.001 mm, "wave centred"
    assert front.names.t.bb.top < front.wave.bb.bottom, "names under the wave"
    assert front.date.t.bb.top < front.names.t.bb.bottom and front.date.t.bb.bottom > front.body.bb.bottom,
        "date under the names, on the plate"
    assert foot_l.seat.cut.bb.width == 6.2 mm and foot_l.seat.cut.bb.height == 12 mm, "seat 6.2 x 12"
    assert foot_l.body.bb.width == 60 mm and foot_l.body.bb.height == 25 mm, "feet 60 x 25"
}
