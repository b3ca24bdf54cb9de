# Request: a camp-kitchen organizer that straps round a tree, 6 mm ply. A 400 x 90 mm board
# with R8 corners; at each end two 42 x 5 mm strap slots (for 38 mm webbing), their centres
# 12 and 25 mm in from the end. Four J-hooks standing straight out of the board at x = -120,
# -40, 40, 120 mm: each hook 60 mm tall at the board, a 14 mm arm reaching 50 mm out with an
# upturned tip, an R5 inner corner, glued with two 10 mm tabs through mortises in the board
# (centred 12 mm below the board's middle). "CAMP KITCHEN" engraved filled in bold letters
# 9 mm tall across the top, and MUGS, TOWEL, LAMP, PAN engraved under the hooks.

import "std/joints.aidl"

thickness 6 mm

t = 6 mm
board_w = 400 mm
board_h = 90 mm
hook_xs = [-120 mm, -40 mm, 40 mm, 120 mm]
names = ["MUGS", "TOWEL", "LAMP", "PAN"]
hook_h = 60 mm
yc = -12 mm        # mortise centre below the board's middle

def j_hook() -> solid {
    shank = RoundedRectangle(bottom_left=(0, 0), width=18, height=hook_h,
                             corner_radii=[0, 6, 0, 0])
    arm = Stroke(Polyline([(9, 9), (43, 9), (50, 28)]), width=14)
    Fillet((18, 16), 5)
    tabs = tab_and_slot(part="tab", length=hook_h, thickness=t, tabs=2, tab=10 mm, screw=0,
                        rotation=90 deg, cx=0 mm, cy=hook_h / 2)
}

assembly organizer {
    solid board {
        plank = RoundedRectangle(center=(0, 0), width=board_w, height=board_h, corner_radius=8)
        for s in [-1, 1] {
            hole strap_in { h = Slot(center=(s * (board_w / 2 - 25), 0), length=42, width=5,
                                     rotation=90 deg) }
            hole strap_out { h = Slot(center=(s * (board_w / 2 - 12), 0), length=42, width=5,
                                      rotation=90 deg) }
        }
        for i in range(4) {
            m = tab_and_slot(part="slot", length=hook_h, thickness=t, tabs=2, tab=10 mm,
                             screw=0, rotation=90 deg, cx=hook_xs[i], cy=yc)
        }
        drawing title {
            word = Text("CAMP KITCHEN", position=(0, 32), size=9, font="sans:Bold",
                        valign="middle", fill=true)
        }
        drawing labels {
            for i in range(4) {
                name = Text(names[i], position=(hook_xs[i], -39), size=5, valign="middle")
            }
        }
        Fixed(plank)
    }

    for i in range(4) {
        hook = j_hook()
        hook.bb.left == -board_w / 2 + i * 70 mm
        hook.bb.top == -board_h / 2 - 10 mm
        # out of the board's front face, tab tips flush with its back face
        Place(hook, position=(hook_xs[i] + t / 2, 0, yc - hook_h / 2), face="left", up="up")
    }
    Place(board, position=(0, 0, 0), face="front", up="up")

    assert board.plank.width == 400 mm and board.plank.height == 90 mm
    assert len(board.strap_in) == 2 and len(board.strap_out) == 2
    assert board.strap_in[0].h.length == 42 mm and board.strap_in[0].h.width == 5 mm
    assert board.strap_out[1].h.center.x - board.strap_in[1].h.center.x == 25 mm - 12 mm
    assert board.plank.bb.right - board.strap_out[1].h.center.x == 12 mm
    assert len(hook) == 4
    assert hook[0].bb.height == 60 mm, "60 mm tall at the board"
    assert hook[0].bb.width == 50 mm + 7 mm, "arm reaches 50 mm out (to the tip's centre)"
    assert board.title.word.size == 9 mm
}
