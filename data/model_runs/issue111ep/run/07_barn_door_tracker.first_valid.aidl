# Request (science): a hand-driven barn-door star tracker (Haig mount) for wide-field
# astrophotography, 6 mm birch ply. Two boards 300 x 80 mm joined by a piano hinge across
# one end (three 2 mm pilot holes for its screws, 8 mm from that end, at the middle and
# 30 mm either side). The drive is an M6 rod (1 mm pitch) turned one turn a minute, so it
# stands 228.6 mm from the hinge axis: the base board has an 8 mm hole there for the rod's
# M6 T-nut, and a 7.9 mm hole at 120 mm for a 1/4"-20 T-nut onto the tripod. The top board
# has a 10 mm hole at 150 mm for the ball head's 3/8" bolt and an engraved ring (12 mm) where
# the rod's tip pushes. Polar sight: two vanes 40 mm wide standing 50 mm above the top
# board, 20 mm from the hinge end, 30 mm either side of the centre line, each on one 20 mm
# glued tenon; the near vane has a 2 mm peep hole, the far one a 12 mm ring, both 35 mm up.
# A 70 mm knob on the rod's lower end: an M6 nut trap in the middle, 24 round finger notches
# (7 mm) round its rim, 12 engraved ticks each 5 seconds apart, labelled 0, 5 ... 55.
# Engraved on the top board: "HAIG M6  r = 228.6".

import "std/joints.aidl"
import "std/fasteners.aidl"

units mm
t = 6 mm
thickness t
kerf 0.15 mm

board_l = 300 mm
board_w = 80 mm
drive_r = 228.6 mm
vane_x = 20 mm
vane_y = 30 mm
vane_w = 40 mm
vane_h = 50 mm
sight_h = 35 mm
open_angle = 5 deg

def vane(peep=2 mm) -> solid {
    body = Rectangle(corner=(-vane_w / 2, -t), opposite=(vane_w / 2, vane_h))
    tenon = tab_and_slot(part="tab", length=vane_w, thickness=t, tabs=1, tab=20 mm, screw=0,
                         rotation=180 deg, cx=0, cy=-t)
    hole sight { c = Circle(center=(0, sight_h), diameter=peep) }
}

assembly tracker {
    solid base {
        board = Rectangle(corner=(0, -board_w / 2), opposite=(board_l, board_w / 2))
        for k in range(3) {
            hole hinge { c = Circle(center=(8, (k - 1) * 30), diameter=2) }
        }
        hole drive { c = Circle(center=(drive_r, 0), diameter=8) }
        hole tripod { c = Circle(center=(120, 0), diameter=7.9) }
    }

    solid top {
        board = Rectangle(corner=(0, -board_w / 2), opposite=(board_l, board_w / 2))
        for k in range(3) {
            hole hinge { c = Circle(center=(8, (k - 1) * 30), diameter=2) }
        }
        hole ballhead { c = Circle(center=(150, 0), diameter=10) }
        mortise_near = tab_and_slot(part="slot", length=vane_w, thickness=t, tabs=1, tab=20 mm,
                                    screw=0, cx=vane_x, cy=-vane_y)
        mortise_far = tab_and_slot(part="slot", length=vane_w, thickness=t, tabs=1, tab=20 mm,
                                   screw=0, cx=vane_x, cy=vane_y)
        drawing marks {
            pad = Circle(center=(drive_r, 0), diameter=12)
            name = Text("HAIG M6  r = 228.6", position=(250, -28), size=5, valign="middle")
        }
    }

    near = vane(peep=2 mm)
    far = vane(peep=12 mm)

    solid knob {
        disc = Circle(center=(0, 0), diameter=70)
        nut = nut_trap(size=6, cx=0, cy=0)
        for k in range(24) {
            hole grip { c = Circle(center=polar((0, 0), 35, k * 15 deg), diameter=7) }
        }
        drawing dial {
            for k in range(12) {
                tick = Line(polar((0, 0), 25, 90 deg - k * 30 deg), polar((0, 0), 30, 90 deg - k * 30 deg))
            }
            ring = Circle(center=(0, 0), radius=18, construction=true)
            for k in range(12) {
                label = Text(str(5 * k), along=ring, angle=90 deg - k * 30 deg, size=4)
            }
        }
    }

    # cutting layout
    Above(top, base, gap=6)
    AlignLeft(top, base)
    RightOf(near, base, gap=6)
    AlignBottom(near, base)
    RightOf(far, near, gap=6)
    AlignBottom(far, base)
    Above(knob, near, gap=6)
    AlignLeft(knob, near)

    # in 3D: the base flat, the top board hinged at x = 0 and opened 5 degrees, the vanes on
    # it, the knob 30 mm under the base on the rod
    Place(base, position=(0, 0, 0))
    Place(top, position=(0, 0, t), rotation=(0 deg, -open_angle, 0 deg))
    Place(near, position=(vane_x * cos(open_angle) - t * sin(open_angle), -vane_y + t,
                          t + vane_x * sin(open_angle) + t * cos(open_angle)),
          rotation=(90 deg, -open_angle, 0 deg))
    Place(far, position=(vane_x * cos(open_angle) - t * sin(open_angle), vane_y + t,
                         t + vane_x * sin(open_angle) + t * cos(open_angle)),
          rotation=(90 deg, -open_angle, 0 deg))
    Place(knob, position=(drive_r, 0, -30))

    # the request's numbers
    assert base.board.width == 300 mm and base.board.height == 80 mm
    assert base.drive.c.center.x - base.board.bb.left == 228.6 mm
    assert base.tripod.c.center.x - base.board.bb.left == 120 mm
    assert top.ballhead.c.center.x - top.board.bb.left == 150 mm
    assert top.marks.pad.center.x - top.board.bb.left == 228.6 mm
    assert base.hinge[0].c.center.x - base.board.bb.left == 8 mm
    assert base.hinge[2].c.center.y - base.hinge[1].c.center.y == 30 mm
    assert near.body.width == 40 mm and near.body.height - t == 50 mm
    assert near.sight.c.center.y - near.body.bb.bottom - t == 35 mm
    assert near.sight.c.diameter == 2 mm and far.sight.c.diameter == 12 mm
    assert top.mortise_far.slot[0].bb.center_y - top.board.bb.center_y == 30 mm
    assert top.mortise_far.slot[0].bb.center_x - top.board.bb.left == 20 mm
    assert knob.disc.diameter == 70 mm and len(knob.grip) == 24 and len(knob.dial.tick) == 12
    # the 1 mm pitch at one turn a minute keeps sidereal time at this radius
    assert abs(1 mm * 1436.07 / (2 * pi) - 228.6 mm) < 0.1 mm
    # the engraving stays on the board and off the rod's pad
    assert top.marks.name.bb.right <= top.board.bb.right - 3 mm
    assert top.marks.name.bb.bottom >= top.board.bb.bottom + 3 mm
    assert distance(top.marks.name, top.marks.pad) >= 2 mm
}
