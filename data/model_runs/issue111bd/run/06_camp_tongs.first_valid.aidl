# Request (camping): campfire toast tongs from one strip of 3 mm birch ply, 370 mm long
# overall. The arms are 26 mm wide; a 40 mm long living hinge across the middle lets the
# strip fold into a U with a 10 mm inside radius (pitch 2 mm, 20 mm cuts, 3 mm bridges).
# Each end is a 50 x 40 mm paddle with 8 mm rounded corners and three 20 x 4 mm drain slots
# along it, 10 mm apart. "CAMP" on one arm and "TONGS" on the other, 7 mm stroke letters,
# centred 90 mm from the middle, engraved on the faces that end up outside the fold.

import "std/plates.aidl"

thickness 3 mm

total = 370 mm
arm_w = 26 mm
hinge_len = 40 mm
paddle_l = 50 mm
paddle_w = 40 mm

def drain_slots() -> hole {
    for k in range(3) {
        s = Slot(center=(0, -10 mm + 10 mm * k), length=20, width=4)
    }
}

assembly kit {
    solid tongs {
        band = Rectangle(center=(0, 0), width=total - 2 * paddle_l + 2 mm, height=arm_w)
        left_paddle = RoundedRectangle(center=(-total / 2 + paddle_l / 2, 0), width=paddle_l,
                                       height=paddle_w, corner_radius=8)
        right_paddle = RoundedRectangle(center=(total / 2 - paddle_l / 2, 0), width=paddle_l,
                                        height=paddle_w, corner_radius=8)
        hinge = living_hinge(width=hinge_len, height=arm_w, pitch=2 mm, cut=20 mm, bridge=3 mm,
                             cx=0 mm, cy=0 mm)
        left_drains = drain_slots()
        right_drains = drain_slots()
        CenterInside(left_drains, left_paddle)
        CenterInside(right_drains, right_paddle)
        drawing words {
            w1 = Text("CAMP", position=(-90, 0), size=7, valign="middle")
            w2 = Text("TONGS", position=(90, 0), size=7, valign="middle")
        }
        Fixed(band)
    }

    Place(tongs, position=(0, 0, 0))
    # folded: the right arm turns over the left, engraved faces outside
    Bend(tongs, at=0, angle=-180 deg, radius=10)

    # the request's numbers
    assert tongs.right_paddle.bb.right - tongs.left_paddle.bb.left == 370 mm, "370 long"
    assert tongs.band.height == 26 mm, "arms 26 wide"
    assert tongs.left_paddle.width == 50 mm and tongs.left_paddle.height == 40 mm, "paddles 50 x 40"
    assert len(tongs.left_drains.s) == 3, "three drain slots"
    assert abs(pi * (10 mm + 1.5 mm) - hinge_len) < 5 mm, "the hinge is long enough for the fold"
    assert tongs.words.w2.position.x - tongs.band.center.x == 90 mm, "words 90 from the middle"
}
