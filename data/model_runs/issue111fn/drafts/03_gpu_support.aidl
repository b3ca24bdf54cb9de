# Request: a sag support for the graphics card in my PC, cut from 5 mm clear acrylic. It
# stands on the PSU shroud and holds the card's lower edge 100 mm above it. A foot 80 x 80
# with R8 corners and a cap 60 x 60 with R6 corners, joined by two posts 60 wide that cross
# in a cross halving (each cut halfway), each post with two 16 mm tenons at each end through
# both plates (glued). Six 16 mm round windows in each post, two columns 30 apart; "100"
# engraved on the foot.

import "std/joints.aidl"

thickness 5 mm

T = 5 mm
H = 100 mm            # shroud to card
POST_W = 60 mm
CLEAR = H - 2 * T     # post between the plates

def post(from_bottom=false) -> solid {
    body = Rectangle(bottom_left=(-POST_W / 2, 0), width=POST_W, height=H)
    bottom = tab_and_slot(part="tab", length=POST_W, thickness=T, tabs=2, tab=16 mm, screw=0,
                          rotation=180 deg, cx=0, cy=0)
    top = tab_and_slot(part="tab", length=POST_W, thickness=T, tabs=2, tab=16 mm, screw=0,
                       cx=0, cy=H)
    if from_bottom {
        half = cross_halving(depth=CLEAR / 2, thickness=T, rotation=180 deg, cx=0, cy=T)
    } else {
        half = cross_halving(depth=CLEAR / 2, thickness=T, cx=0, cy=H - T)
    }
    hole win {
        for r in range(3) {
            for s in [-15, 15] {
                c = Circle(center=(s, T + CLEAR / 2 + (r - 1) * 23), diameter=16)
            }
        }
    }
}

def plate(side=80 mm, r=8 mm) -> solid {
    body = RoundedRectangle(center=(0, 0), width=side, height=side, corner_radius=r)
    along_x = tab_and_slot(part="slot", length=POST_W, thickness=T, tabs=2, tab=16 mm,
                           screw=0, cx=0, cy=0)
    along_y = tab_and_slot(part="slot", length=POST_W, thickness=T, tabs=2, tab=16 mm,
                           screw=0, rotation=90 deg, cx=0, cy=0)
}

assembly support {
    foot = plate(side=80 mm, r=8 mm)
    cap = plate(side=60 mm, r=6 mm)
    post_a = post(from_bottom=false)
    post_b = post(from_bottom=true)
    drawing mark {
        t = Text("100", position=(0, 0), size=7, font="sans:Bold", valign="middle", fill=true)
    }
    At(mark.t.position, foot.body.center, dx=22, dy=-22)
    CutInto(mark, foot)

    RightOf(cap, foot, gap=8)
    AlignBottom(cap, foot)
    RightOf(post_a, cap, gap=8)
    AlignBottom(post_a, foot)
    RightOf(post_b, post_a, gap=8)
    AlignBottom(post_b, foot)

    Place(foot, position=(0, 0, 0), face="up")
    Place(cap, position=(0, 0, H - T), face="up")
    Place(post_a, position=(0, T / 2, 0), face="front", up="up")
    Place(post_b, position=(T / 2, 0, 0), face="left", up="up")

    assert post_a.body.bb.height == 100 mm, "shroud to card 100 mm (tenon tips flush)"
    assert foot.body.bb.width == 80 mm and cap.body.bb.width == 60 mm, "foot 80, cap 60"
    assert post_a.half.cut.bb.height + post_b.half.cut.bb.height == 100 mm - 2 * 5 mm,
        "the halvings meet"
    assert len(post_a.win.c) == 3, "three rows of windows"
}
