# Request (sport): a table skittles set for the pub, 3 mm ply. Each skittle is two identical
# turned-pin profiles (112.5 mm tall, 30 mm foot, 39 mm belly, 15 mm neck, round head) slotted
# together crosswise: one with a slot from the top, one from the bottom, each half the height,
# 0.1 mm clearance; this program draws one skittle's pair, to be cut 9 times. The board is
# 220 x 260 mm, r12 corners, engraved with 9 spots 40 mm across in a diamond (a 3 x 3 grid at
# 50 mm, turned 45 deg) centred 30 mm above the board's centre, a throw line 95 mm below the
# centre and "SKITTLES" engraved filled under it; a 60 mm puck with a 20 mm finger hole.

import "std/joints.aidl"

units mm
thickness 3 mm

ply = 3 mm
pin_h = 112.5 mm
spot_pitch = 50 mm
half_profile = [(15, 0), (18.8, 15), (19.5, 35), (15, 56), (7.5, 77), (8, 87), (11.2, 97),
                (8.8, 107), (0, 112.5)]

def pin(from_top=true) -> solid {
    profile = Spline(mirror(half_profile, about="y"), closed=true, corners=[0, -1])
    if from_top {
        slot = cross_halving(depth=56.25 mm, thickness=3 mm, clearance=0.1 mm, rotation=0 deg,
                             cx=0 mm, cy=112.5 mm)
    } else {
        slot = cross_halving(depth=56.25 mm, thickness=3 mm, clearance=0.1 mm, rotation=180 deg,
                             cx=0 mm, cy=0 mm)
    }
}

assembly skittles {
    solid board {
        plate = RoundedRectangle(center=(0, 0), width=220, height=260, corner_radius=12)
        drawing marks {
            for i in range(3) {
                for j in range(3) {
                    spot = Circle(center=((i - j) * spot_pitch * cos(45 deg),
                                          30 + (i + j - 2) * spot_pitch * sin(45 deg)), diameter=40)
                }
            }
            throw = Line((-90, -95), (90, -95))
            word = Text("SKITTLES", position=(0, -118), size=12, font="sans:Bold", fill=true)
        }
    }
    pin_a = pin(from_top=true)
    pin_b = pin(from_top=false)
    solid puck {
        disc = Circle(center=(0, 0), diameter=60)
        hole grip { c = Circle(center=(0, 0), diameter=20) }
    }

    # 3D: one skittle stands crossed on the middle spot
    Place(board, position=(0, 0, 0))
    Place(pin_a, rotation=(90 deg, 0, 0), position=(0, 30 + ply / 2, ply))
    Place(pin_b, rotation=(90 deg, 0, 90 deg), position=(-ply / 2, 30, ply))

    # flat on the sheet
    RightOf(pin_a, board, gap=5)
    AlignTop(pin_a, board)
    RightOf(pin_b, pin_a, gap=5)
    AlignTop(pin_b, pin_a)
    Below(puck, pin_a, gap=5)
    AlignLeft(puck, pin_a)

    assert len(board.marks.spot) == 3 and len(board.marks.spot[0]) == 3, "9 spots"
    assert distance(board.marks.spot[0][0].center, board.marks.spot[1][0].center) == 50 mm, "spots 50 mm apart"
    assert board.marks.spot[1][1].center.y - board.plate.center.y == 30 mm, "diamond 30 mm above the centre"
    assert board.plate.center.y - board.marks.throw.start.y == 95 mm, "throw line 95 mm below the centre"
    assert pin_a.profile.bb.height == 112.5 mm and pin_a.profile.bb.width >= 39 mm, "pin 112.5 tall, 39 belly"
    assert pin_a.slot.bb.height + pin_b.slot.bb.height == 112.5 mm, "the two slots meet"
    assert puck.disc.diameter == 60 mm and puck.grip.c.diameter == 20 mm, "puck 60, finger hole 20"
}
