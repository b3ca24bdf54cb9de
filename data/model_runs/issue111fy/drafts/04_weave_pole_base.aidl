# Request: a base for one pole of a dog-agility weave set (cut six, numbered 1 to 6), 6 mm
# exterior ply, for 25 mm dowel poles. Two feet 300 long x 80 tall crossed in a "+" by a
# cross halving (each slotted 40 mm, 0.1 mm clearance), their top outer corners chamfered
# 20 mm. At the crossing the pole stands in a socket: each foot has a notch 25.5 wide x 25
# deep in the middle of its top edge. A collar disc 90 mm across with a 25.5 mm hole sits on
# the feet and locks them square: each foot has two tabs 10 wide x 6 tall on its top edge,
# centred 25 mm either side of the middle, into four slots in the collar (10.2 x 6.2).
# "POLE 1" (the number from a param) engraved 5 mm tall round the collar's top, outside the
# slots.

thickness 6 mm

import "std/joints.aidl"

param pole_no = 1, min = 1, max = 6

T = 6 mm
foot_l = 300 mm
foot_h = 80 mm
sock_w = 25.5 mm
sock_d = 25 mm
tab_x = 25 mm

def foot(from_top=true) -> solid {
    body = Rectangle(corner=(-foot_l / 2, 0), opposite=(foot_l / 2, foot_h))
    tab_l = Rectangle(center=(-tab_x, foot_h + T / 2), width=10, height=T)
    tab_r = Rectangle(center=(tab_x, foot_h + T / 2), width=10, height=T)
    hole socket {
        s = Rectangle(center=(0, foot_h - sock_d / 2), width=sock_w, height=sock_d)
    }
    if from_top {
        half = cross_halving(depth=foot_h / 2, thickness=T, clearance=0.1 mm, cx=0, cy=foot_h)
    } else {
        half = cross_halving(depth=foot_h / 2, thickness=T, clearance=0.1 mm, rotation=180 deg,
                             cx=0, cy=0)
    }
    Chamfer(at=[body.top_left, body.top_right], distance=20)
}

assembly weave_base {
    foot_a = foot(from_top=true)
    foot_b = foot(from_top=false)

    solid collar {
        disc = Circle(center=(0, 0), diameter=90)
        hole pole {
            c = Circle(center=(0, 0), diameter=sock_w)
        }
        hole slots {
            sx1 = Rectangle(center=(-tab_x, 0), width=10.2, height=T + 0.2)
            sx2 = Rectangle(center=(tab_x, 0), width=10.2, height=T + 0.2)
            sy1 = Rectangle(center=(0, -tab_x), width=T + 0.2, height=10.2)
            sy2 = Rectangle(center=(0, tab_x), width=T + 0.2, height=10.2)
        }
        drawing number {
            ring = Circle(center=(0, 0), radius=35, construction=true)
            # FIX after the first valid program: W0115 said nothing reads `pole_no`, though
            # the f-string did (`--set pole_no=4` engraved "POLE 4"): a false alarm; written
            # with str() to see whether the check then sees the use
            t = Text("POLE " + str(pole_no), along=ring, size=5)
        }
    }

    # flat on the sheet
    Below(foot_b, foot_a, gap=8)
    AlignLeft(foot_b, foot_a)
    RightOf(collar, foot_a, gap=8)
    AlignTop(collar, foot_a)

    # in 3D: foot a along x, foot b along y, the collar on top
    Place(foot_a, position=(0, T / 2, 0), face="front", up="up")
    Place(foot_b, position=(-T / 2, 0, 0), face="right", up="up")
    Place(collar, position=(0, 0, foot_h), face="up", up="back")

    # the request's numbers
    assert foot_a.body.width == 300 mm and foot_a.body.height == 80 mm, "feet 300 x 80"
    assert foot_a.half.depth + foot_b.half.depth == 80 mm, "halvings meet: 40 + 40"
    assert foot_a.half.depth == 40 mm, "each slotted 40"
    assert foot_a.socket.s.width == 25.5 mm and foot_a.socket.s.height == 25 mm,
        "socket 25.5 x 25"
    assert foot_a.socket.s.width > 25 mm, "the 25 mm pole fits"
    assert foot_a.tab_r.center.x - foot_a.tab_l.center.x == 2 * 25 mm, "tabs 25 either side"
    assert foot_a.tab_l.bb.right < foot_a.socket.bb.left - 3 mm, "tabs clear of the socket"
    assert collar.disc.diameter == 90 mm and collar.pole.c.diameter == 25.5 mm, "collar 90/25.5"
    assert collar.slots.sx2.center.x - collar.slots.sx1.center.x == 2 * 25 mm, "slots match tabs"
    assert collar.slots.sx1.width == 10.2 mm, "slots 10.2 x 6.2"
    assert collar.number.t.size == 5 mm, "number 5 tall"
    assert distance(collar.number, collar.slots) >= 2 mm, "number outside the slots"
}
