# Request (crafts): a tassel maker in 6 mm ply for three tassel lengths, 50, 75 and 100 mm.
# A base bar 170 x 35 mm with three forks standing on it, 60 mm apart (centres). Each fork is
# two 12 mm prongs with a 6 mm slot between them (30 mm across the fork); the prongs reach
# 50, 75 and 100 mm above the base's top edge and end in half-round tips. The slot runs on
# 10 mm down into the base so the scissors reach the wrapped yarn's bottom loops. Every
# inside corner rounded r 3 mm. Each fork's length engraved under it on the base ("50", "75",
# "100"), bold filled 8 mm.

thickness 6 mm

LENGTHS = [50, 75, 100]
PRONG_W = 12 mm
SLOT_W = 6 mm
FORK_W = 2 * PRONG_W + SLOT_W
PITCH = 60 mm
BASE_W = 170 mm
BASE_H = 35 mm

solid tassel_maker {
    base = Rectangle(bottom_left=(-BASE_W / 2, -BASE_H), width=BASE_W, height=BASE_H)
    for i in range(3) {
        solid fork {
            left = RoundedRectangle(bottom_left=((i - 1) * PITCH - FORK_W / 2, -1), width=PRONG_W,
                                    height=LENGTHS[i] + 1, corner_radii=[PRONG_W / 2, PRONG_W / 2, 0, 0])
            right = RoundedRectangle(bottom_left=((i - 1) * PITCH + SLOT_W / 2, -1), width=PRONG_W,
                                     height=LENGTHS[i] + 1, corner_radii=[PRONG_W / 2, PRONG_W / 2, 0, 0])
        }
        hole slot {
            s = Rectangle(bottom_left=((i - 1) * PITCH - SLOT_W / 2, -10), width=SLOT_W, height=12)
        }
        drawing label {
            t = Text(str(LENGTHS[i]), position=((i - 1) * PITCH, -22), size=8, font="sans:Bold",
                     valign="middle", fill=true)
        }
    }
    Fillet(3)

    assert len(fork) == 3, "three forks"
    assert fork[0].left.bb.top - base.bb.top == 50 mm, "50 mm prongs"
    assert fork[1].left.bb.top - base.bb.top == 75 mm, "75 mm prongs"
    assert fork[2].right.bb.top - base.bb.top == 100 mm, "100 mm prongs"
    assert fork[1].right.bb.left - fork[1].left.bb.right == 6 mm, "6 mm slot"
    assert fork[1].right.bb.right - fork[1].left.bb.left == 30 mm, "30 mm across"
    assert fork[2].left.bb.left - fork[1].left.bb.left == 60 mm, "60 mm apart"
    assert base.bb.top - slot[0].s.bb.bottom == 10 mm, "slot 10 mm into the base"
    assert base.width == 170 mm and base.height == 35 mm, "base 170 x 35"
}
