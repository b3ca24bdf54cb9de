# Request: a quarter-pipe for fingerboards (finger skateboards), all 3 mm ply, glued.
# 100 mm wide; three identical side profiles (two 3 mm in from the edges, one in the middle):
# a quarter-circle transition of R60 (on the profiles; the riding skin lies on it), 70 mm to
# the top of the deck, a 40 mm deck, the profile starting where the curve is 2 mm high. Each
# profile has two 10 mm tabs up into the deck and two 12 mm tabs back into the back plate,
# and a 24 mm lightening hole. Deck: 43 x 100 plate on top, its front edge over the skin (the
# coping edge). Back plate 100 x 67 under the deck. Riding skin: one 100 mm wide strip with a
# living hinge over the whole 90 deg bend (inside radius 57 = 60 - 3), a 5 mm flat lead-in on
# the table and 7 mm straight up to the deck. "FINGERBOARD CO." engraved on the back plate.

import "std/joints.aidl"
import "std/plates.aidl"

thickness 3 mm

t = 3 mm
R = 60 mm            # transition radius on the profiles
H = 70 mm            # table to the top of the deck
D = 40 mm            # deck depth on the profiles
W = 100 mm           # ramp width
x0 = sqrt(R ** 2 - (R - 2 mm) ** 2)    # where the curve is 2 mm high
ys = [-(W / 2 - t - t / 2), 0 mm, W / 2 - t - t / 2]   # middles of the three profiles
bend_w = 90 deg * (R - t + t / 2) / 1 rad   # the band the bend takes on the flat sheet
lead = 5 mm
rise = H - t - R     # straight part of the skin under the deck
skin_len = lead + bend_w + rise

def profile() -> solid {
    arc = Arc(center=(0, R), radius=R, start_angle=270 deg + asin(x0 / R), end_angle=360 deg)
    front = Line((x0, 0), (x0, 2))
    rise_edge = Line((R, R), (R, H))
    top = Line((R, H), (R + D, H))
    back = Line((R + D, H), (R + D, 0))
    ground = Line((R + D, 0), (x0, 0))
    top_tabs = tab_and_slot(part="tab", length=D, thickness=t, tabs=2, tab=10 mm, screw=0,
                            cx=R + D / 2, cy=H)
    back_tabs = tab_and_slot(part="tab", length=H, thickness=t, tabs=2, tab=12 mm, screw=0,
                             rotation=-90 deg, cx=R + D, cy=H / 2)
    hole lighten { c = Circle(center=(80, 30), diameter=24) }
}

assembly quarter_pipe {
    for i in range(3) {
        side = profile()
        side.bb.left == x0 + i * 110 mm
        side.bb.bottom == 0 mm
        Place(side, position=(0, ys[i] + t / 2, 0), face="front", up="up")
    }

    solid deck {
        plate = Rectangle(bottom_left=(R - t, -W / 2), width=D + t, height=W)
        for i in range(3) {
            m = tab_and_slot(part="slot", length=D, thickness=t, tabs=2, tab=10 mm, screw=0,
                             cx=R + D / 2, cy=ys[i])
        }
    }

    solid back {
        plate = Rectangle(bottom_left=(-W / 2, 0), width=W, height=H - t)
        for i in range(3) {
            m = tab_and_slot(part="slot", length=H, thickness=t, tabs=2, tab=12 mm, screw=0,
                             rotation=90 deg, cx=ys[i], cy=H / 2)
        }
        drawing maker {
            name = Text("FINGERBOARD CO.", position=(0, 8), size=5, valign="middle")
        }
    }

    solid skin {
        strip = Rectangle(bottom_left=(0, -W / 2), width=skin_len, height=W)
        flex = living_hinge(width=bend_w, height=W, cx=lead + bend_w / 2, cy=0 mm)
    }

    # flat on the sheet
    deck.bb.left == x0 + 3 * 110 mm
    deck.bb.bottom == 0 mm
    back.bb.left == x0 + 3 * 110 mm + 60 mm
    back.bb.bottom == 0 mm
    skin.bb.left == 0 mm
    skin.bb.top == -10 mm

    # assembled: x is depth, y across, z up
    Place(deck, position=(0, 0, H - t))
    Place(back, position=(R + D - t, 0, 0), face="right", up="up")
    Place(skin, position=(-lead, 0, 0))
    Bend(skin, at=lead + bend_w / 2, angle=90 deg, radius=R - t)

    assert len(side) == 3
    assert side[0].bb.height == 70 mm, "70 mm to the top of the deck"
    assert side[0].arc.radius == 60 mm
    assert side[0].top.length == 40 mm
    assert side[0].front.length == 2 mm
    assert ys[2] - ys[0] == 100 mm - 2 * 3 mm - 3 mm, "outer profiles 3 mm in from the edges"
    assert deck.plate.width == 43 mm and deck.plate.height == 100 mm
    assert back.plate.width == 100 mm and back.plate.height == 67 mm
    assert skin.strip.height == 100 mm
    assert skin.strip.width - bend_w == 5 mm + 7 mm
    assert side[0].lighten.c.diameter == 24 mm
}
