# Request: a ramp for a rabbit hutch door, 6 mm exterior ply.
# - A plank 560 long x 160 wide, its bottom end's corners rounded 8 mm.
# - Eight rungs 140 mm long standing 12 mm proud of the plank (top corners rounded 4 mm), at
#   60 mm pitch, the first 40 mm from the bottom end; each glued in with two 30 mm tabs.
# - Under the top end, two hangers 60 long x 30 deep (below the plank), along the plank's
#   long edges 10 mm in from them, flush with the top end, each with one 30 mm tenon through
#   the plank and a notch 20 wide x 25 deep, 10 mm from the top end, that drops over the
#   hutch's 18 mm door sill.
# - The rabbit's name "THUMPER" engraved (12 mm) below the first rung.

import "std/joints.aidl"

units mm
thickness 6 mm

T = 6 mm
PLANK_L = 560 mm
PLANK_W = 160 mm
RUNGS = 8
RUNG_L = 140 mm
RUNG_UP = 12 mm
HANG_L = 60 mm
HANG_D = 30 mm
HANG_X = PLANK_W / 2 - 10 mm - T / 2

def rung() -> solid {
    # tab tips on y = 0 (flush with the plank's underside), the rung above
    body = RoundedRectangle(center=(0, (T + RUNG_UP) / 2), width=RUNG_L, height=T + RUNG_UP,
                            corner_radii=[4, 4, 0, 0])
    tabs = tab_and_slot(part="tab", length=RUNG_L, thickness=T, tabs=2, tab=30 mm, screw=0,
                        rotation=180 deg, cx=0 mm, cy=0 mm)
}

def hanger() -> solid {
    # x along the plank (the top end at x = HANG_L / 2), tenon tip on y = 0 (the plank's top)
    body = Rectangle(center=(0, -(T + HANG_D) / 2), width=HANG_L, height=T + HANG_D)
    tenon = tab_and_slot(part="tab", length=HANG_L, thickness=T, tabs=1, tab=30 mm, screw=0,
                         cx=0 mm, cy=0 mm)
    hole notch {
        n = Rectangle(center=(HANG_L / 2 - 20, -(T + HANG_D) + 12.5), width=20, height=25)
        out = Rectangle(center=(HANG_L / 2 - 20, -(T + HANG_D) - 0.5), width=20, height=1,
                        overrun=true)
    }
}

assembly ramp {
    solid plank {
        body = RoundedRectangle(bottom_left=(-PLANK_W / 2, 0), width=PLANK_W, height=PLANK_L,
                                corner_radii=[0, 0, 8, 8])
        for i in range(RUNGS) {
            rung_mortise = tab_and_slot(part="slot", length=RUNG_L, thickness=T, tabs=2,
                                        tab=30 mm, screw=0, cx=0 mm, cy=40 mm + i * 60 mm)
        }
        left_mortise = tab_and_slot(part="slot", length=HANG_L, thickness=T, tabs=1, tab=30 mm,
                                    screw=0, rotation=90 deg, cx=-HANG_X, cy=PLANK_L - HANG_L / 2)
        right_mortise = tab_and_slot(part="slot", length=HANG_L, thickness=T, tabs=1, tab=30 mm,
                                     screw=0, rotation=90 deg, cx=HANG_X, cy=PLANK_L - HANG_L / 2)
        drawing name {
            t = Text("THUMPER", position=(0, 18), size=12, valign="middle")
        }
    }

    for i in range(RUNGS) {
        r = rung()
        RightOf(r, plank, gap=10)
        r.bb.bottom == plank.bb.bottom + i * (T + RUNG_UP + 6)
        Place(r, rotation=(90 deg, 0, 0), position=(0, 40 mm + i * 60 mm + T / 2, 0))
    }
    for j in range(2) {
        h = hanger()
        h.bb.left == plank.bb.right + RUNG_L + 20
        h.bb.bottom == plank.bb.bottom + j * (T + HANG_D + 6)
    }
    # assembled: hangers under the top end, their tenons flush with the plank's top
    Place(h[0], rotation=(90 deg, 0, 90 deg), position=(-HANG_X - T / 2, PLANK_L - HANG_L / 2, T))
    Place(h[1], rotation=(90 deg, 0, 90 deg), position=(HANG_X - T / 2, PLANK_L - HANG_L / 2, T))

    # the request's numbers
    assert plank.body.bb.height == 560 mm and plank.body.bb.width == 160 mm, "plank 560 x 160"
    assert len(r) == 8, "eight rungs"
    assert r[0].body.bb.height - T == 12 mm, "rungs 12 mm proud"
    assert r[0].body.bb.width == 140 mm, "rungs 140 long"
    assert plank.rung_mortise[0].bb.center_y - plank.body.bb.bottom == 40 mm, "first rung 40 mm from the bottom end"
    assert plank.rung_mortise[1].bb.center_y - plank.rung_mortise[0].bb.center_y == 60 mm, "60 mm pitch"
    assert plank.rung_mortise[7].bb.top < plank.left_mortise.bb.bottom, "last rung below the hangers"
    assert plank.left_mortise.bb.left - plank.body.bb.left == 10 mm, "hanger 10 mm in from the edge"
    assert h[0].body.bb.height - T == 30 mm and h[0].body.bb.width == 60 mm, "hangers 60 x 30 below the plank"
    assert h[0].notch.n.bb.width == 20 mm and h[0].notch.n.bb.height == 25 mm, "notch 20 x 25"
    assert h[0].body.bb.right - h[0].notch.n.bb.right == 10 mm, "notch 10 mm from the top end"
    assert plank.body.bb.top - plank.left_mortise.slot[0].bb.top == (HANG_L - 30 mm) / 2,
        "hanger flush with the top end"
}
