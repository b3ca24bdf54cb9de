# Request (kitchen): a countertop rack that stands three chopping boards (up to 20 mm thick)
# upright, one behind the other. 6 mm birch ply, no glue: it slots together.
# - Two rails, 280 mm long front to back, 180 mm apart (centre to centre). Each rail's top is
#   one smooth curve from 80 mm high at the front to 120 mm high at the back, passing 110 mm
#   high at the middle. Underneath, a shallow arch 160 mm wide and 15 mm high between two feet.
# - Three notches 22 mm wide in each rail's top, 60 mm apart (centre to centre), the middle
#   one at the rail's middle; all three bottom out 40 mm above the counter so the boards stand
#   level. Bottom corners of each notch R4.
# - Two cross bars 220 mm long x 40 mm high, 110 mm in front of and behind the middle, joined to
#   the rails by cross halvings (each part slotted 20 mm).
# - "CHOP" engraved on each rail's outer face at the back, 10 mm serif letters.

import "std/joints.aidl"

thickness 6 mm
t = 6 mm

param board = 20 mm, min = 10 mm, max = 30 mm   # thickest board
notch_w = board + 2 mm
rail_len = 280 mm
rail_gap = 180 mm      # centre to centre
bar_at = 110 mm        # the bars' distance in front of / behind the rails' middle

# FIX after the first valid program: the left rail's "CHOP" faced inward (both rails were the
# same part, both turned to face right). s = -1 draws the rail mirrored, to be turned to face left.
def rail(s=1) -> solid {
    bottom = Line((-s * rail_len / 2, 0), (s * rail_len / 2, 0))
    back = Line((s * rail_len / 2, 0), (s * rail_len / 2, 120))
    top = Arc(start=(s * rail_len / 2, 120), through=(0, 110), end=(-s * rail_len / 2, 80))
    front = Line((-s * rail_len / 2, 80), (-s * rail_len / 2, 0))
    hole arch { e = Ellipse(center=(0, 0), rx=80, ry=15) }
    hole notches {
        for i in range(3) {
            n = RoundedRectangle(bottom_left=((i - 1) * 60 mm - notch_w / 2, 40), width=notch_w,
                                 height=90, corner_radii=[0, 0, 4, 4])
        }
    }
    front_halving = cross_halving(depth=20 mm, thickness=t, rotation=180 deg, cx=-bar_at, cy=0)
    back_halving = cross_halving(depth=20 mm, thickness=t, rotation=180 deg, cx=bar_at, cy=0)
    drawing mark {
        word = Text("CHOP", position=(s * 95, 70), size=10, font="serif", fill=true)
    }
}

def bar() -> solid {
    body = Rectangle(bottom_left=(-110, 0), width=220, height=40)
    left_halving = cross_halving(depth=20 mm, thickness=t, cx=-rail_gap / 2, cy=40)
    right_halving = cross_halving(depth=20 mm, thickness=t, cx=rail_gap / 2, cy=40)
}

assembly board_rack {
    left_rail = rail(s=-1)
    right_rail = rail()
    front_bar = bar()
    back_bar = bar()

    # flat on the sheet
    RightOf(right_rail, left_rail, gap=5)
    AlignBottom(right_rail, left_rail)
    Below(front_bar, left_rail, gap=5)
    AlignLeft(front_bar, left_rail)
    RightOf(back_bar, front_bar, gap=5)
    AlignBottom(back_bar, front_bar)

    # assembled: rails stand along y (local x -> +y, front end at -y), bars across x
    Place(left_rail, position=(-rail_gap / 2 + t / 2, 0, 0), face="left", up="up")
    Place(right_rail, position=(rail_gap / 2 - t / 2, 0, 0), face="right", up="up")
    Place(front_bar, position=(0, -bar_at + t / 2, 0), face="front", up="up")
    Place(back_bar, position=(0, bar_at + t / 2, 0), face="front", up="up")

    assert left_rail.bb.width == 280 mm, "rails 280 long"
    assert right_rail.top.start.y - right_rail.bottom.start.y == 120 mm, "120 high at the back"
    assert right_rail.top.end.y - right_rail.bottom.start.y == 80 mm, "80 high at the front"
    assert left_rail.notches.n[1].bb.left - left_rail.notches.n[0].bb.left == 60 mm, "notches 60 apart"
    assert left_rail.notches.n[0].bb.bottom - left_rail.bottom.start.y == 40 mm, "boards stand 40 up"
    assert left_rail.notches.n[0].bb.width == 22 mm, "notches 22 wide"
    assert front_bar.body.bb.width == 220 mm and front_bar.body.bb.height == 40 mm, "bars 220 x 40"
    assert left_rail.arch.e.rx * 2 == 160 mm, "arch 160 wide"
}
