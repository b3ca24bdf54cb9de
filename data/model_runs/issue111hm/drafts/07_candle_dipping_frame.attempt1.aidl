# Request (crafts): a frame for dipping beeswax taper candles, in 6 mm ply. A flat dipping
# bar 340 x 56 mm holds six wicks: three keyhole slits from each long edge (2 mm wide,
# 12 mm deep, ending in a 3 mm hole) at 30 mm pitch, so the two rows of tapers hang 32 mm
# apart; a 24 mm finger hole 20 mm in from each end; "BEESWAX" and "TAPERS" engraved,
# 8 mm letters, between the slits and the finger holes. Between dips the bar rests on a
# drying stand: two trapezoid end frames 320 mm tall, 180 mm wide at the floor and 80 mm at
# the top, each with a saddle notch 58 mm wide and 10 mm deep in its top, joined at the
# floor by a 300 x 40 mm stretcher with cross-halvings (20 mm deep in each), the frames
# 240 mm apart.

import "std/joints.aidl"

thickness 6 mm

T = 6 mm
BAR_L = 340 mm
BAR_W = 56 mm
SLIT = 12 mm
FRAME_H = 320 mm
SPAN = 240 mm       # between the frames' middles

def frame() -> solid {
    body = Trapezoid(center=(0, 0), bottom_width=180, top_width=80, height=FRAME_H)
    hole saddle {
        s = Rectangle(corner=(-29, FRAME_H / 2 - 10), opposite=(29, FRAME_H / 2 + 2))
    }
    foot = cross_halving(depth=20 mm, thickness=T, rotation=180 deg, cx=0, cy=-FRAME_H / 2)
}

assembly candle_dipping_frame {
    solid bar {
        plate = RoundedRectangle(center=(0, 0), width=BAR_L, height=BAR_W, corner_radius=8)
        hole wicks {
            for i in range(3) {
                front_slit = Rectangle(corner=((i - 1) * 30 - 1, -BAR_W / 2 - 1),
                                       opposite=((i - 1) * 30 + 1, -BAR_W / 2 + SLIT))
                front_eye = Circle(center=((i - 1) * 30, -BAR_W / 2 + SLIT), diameter=3)
                back_slit = Rectangle(corner=((i - 1) * 30 - 1, BAR_W / 2 - SLIT),
                                      opposite=((i - 1) * 30 + 1, BAR_W / 2 + 1))
                back_eye = Circle(center=((i - 1) * 30, BAR_W / 2 - SLIT), diameter=3)
            }
        }
        hole grips {
            left = Circle(center=(-BAR_L / 2 + 20, 0), diameter=24)
            right = Circle(center=(BAR_L / 2 - 20, 0), diameter=24)
        }
        drawing words {
            a = Text("TAPERS", (-97, 0), size=8, font="sans:Bold", valign="middle", fill=true)
            b = Text("BEESWAX", (97, 0), size=8, font="sans:Bold", valign="middle", fill=true)
        }
    }
    left_frame = frame()
    right_frame = frame()
    solid stretcher {
        body = Rectangle(center=(0, 0), width=300, height=40)
        left_halving = cross_halving(depth=20 mm, thickness=T, cx=-SPAN / 2, cy=20)
        right_halving = cross_halving(depth=20 mm, thickness=T, cx=SPAN / 2, cy=20)
    }

    bar.bb.center == (0, 250)
    left_frame.bb.center == (-150, 40)
    right_frame.bb.center == (60, 40)
    stretcher.bb.center == (0, -160)

    # standing: the stretcher on edge along x, the frames across it, the bar in the saddles
    Place(stretcher, position=(0, T / 2, 20), face="front", up="up")
    Place(right_frame, position=(SPAN / 2 - T / 2, 0, FRAME_H / 2), face="right", up="up")
    Place(left_frame, position=(-SPAN / 2 - T / 2, 0, FRAME_H / 2), face="right", up="up")
    Place(bar, position=(0, 0, FRAME_H - 10 mm))

    assert bar.plate.width == 340 mm and bar.plate.height == 56 mm, "bar 340 x 56"
    assert len(bar.wicks.front_slit) + len(bar.wicks.back_slit) == 6, "six wicks"
    assert bar.wicks.back_eye[0].center.y - bar.wicks.front_eye[0].center.y == 32 mm,
        "rows 32 apart"
    assert bar.wicks.front_eye[1].center.x - bar.wicks.front_eye[0].center.x == 30 mm,
        "30 mm pitch"
    assert bar.grips.left.center.x - bar.plate.bb.left == 20 mm, "finger hole 20 in"
    assert bar.grips.left.diameter == 24 mm, "24 mm finger holes"
    assert distance(bar.words, bar.wicks) >= 5 mm and distance(bar.words, bar.grips) >= 5 mm,
        "words between the slits and the holes"
    # the bar's grips and words stay off the saddles it rests in
    assert bar.grips.right.bb.left - (SPAN / 2 + T / 2) >= 3 mm, "grip outside the frame"
    assert bar.words.b.bb.right <= SPAN / 2 - T / 2 - 3 mm, "word inside the frame"
    assert left_frame.body.height == 320 mm, "frames 320 tall"
    assert left_frame.body.bottom_width == 180 mm and left_frame.body.top_width == 80 mm,
        "180 at the floor, 80 at the top"
    assert left_frame.saddle.s.bb.width == 58 mm, "58 mm saddle"
    assert left_frame.body.bb.top - left_frame.saddle.s.bb.bottom == 10 mm, "10 mm deep"
    assert stretcher.body.width == 300 mm and stretcher.body.height == 40 mm, "300 x 40"
    assert stretcher.right_halving.cut.bb.center_x - stretcher.left_halving.cut.bb.center_x ==
        240 mm, "frames 240 apart"
    # the halvings add up to the stretcher's height
    assert left_frame.foot.cut.bb.height + stretcher.left_halving.cut.bb.height == 40 mm,
        "halvings meet"
}
