# Request: a stabiliser that stops a 230 g screw-top gas canister (110 mm across) and the
# stove on it from tipping over, in 4 mm birch ply. Two legs 220 x 25 mm stand on edge and
# cross at their middles by a cross halving, so the canister stands on eight arms. Each
# leg's top edge has a recess 111 mm wide (canister + 1 mm) and 4 mm deep in the middle
# that catches the canister's base rim (its inner corners R2, the leg's outer top corners
# R5). A 30 x 8 mm lightening slot in each arm, 82 mm from the middle, and a 4 mm lanyard
# hole 103 mm from the middle to tie the packed pair together. Engraved "230 G" on one
# leg, "CAMP" on the other, 6 mm tall.

import "std/joints.aidl"

t = 4 mm
thickness t

CAN_D = 110 mm
RECESS_W = CAN_D + 1 mm
RECESS_D = 4 mm
LEG_L = 220 mm
LEG_H = 25 mm
MID_H = LEG_H - RECESS_D     # the leg's height under the canister, 21

def leg(word="CAMP", slot_from_top=true) -> solid {
    body = Rectangle(corner=(-LEG_L / 2, 0), opposite=(LEG_L / 2, LEG_H))
    hole recess {
        r = Rectangle(corner=(-RECESS_W / 2, MID_H), opposite=(RECESS_W / 2, LEG_H + 1))
    }
    Fillet(body.top_left, 5)
    Fillet(body.top_right, 5)
    Fillet([recess.r.left, recess.r.bottom], 2)
    Fillet([recess.r.right, recess.r.bottom], 2)
    hole lighten {
        a = Slot(center=(-82, LEG_H / 2), length=30, width=8)
        b = Slot(center=(82, LEG_H / 2), length=30, width=8)
    }
    hole lanyard {
        a = Circle(center=(-103, LEG_H / 2), diameter=4)
        b = Circle(center=(103, LEG_H / 2), diameter=4)
    }
    if slot_from_top {
        halving = cross_halving(depth=MID_H / 2, thickness=t, clearance=0.2, cx=0, cy=MID_H)
    } else {
        halving = cross_halving(depth=MID_H / 2, thickness=t, clearance=0.2, rotation=180,
                                cx=0, cy=0)
    }
    drawing label {
        w = Text(word, position=(-30, LEG_H / 2 - 2), size=6, valign="middle")
    }
}

assembly stabiliser {
    leg_a = leg(word="230 G", slot_from_top=true)
    leg_b = leg(word="CAMP", slot_from_top=false)

    # flat on the sheet
    Below(leg_b, leg_a, gap=8)
    AlignLeft(leg_b, leg_a)

    # in 3D: crossed on the ground
    Place(leg_a, position=(0, t / 2, 0), face="front", up="up")
    Place(leg_b, position=(-t / 2, 0, 0), face="right", up="up")

    assert leg_a.recess.r.width == 111 mm, "recess canister + 1"
    assert leg_a.body.bb.top - leg_a.recess.r.bb.bottom == 4 mm, "recess 4 deep"
    assert leg_a.halving.depth + leg_b.halving.depth == leg_a.recess.r.bb.bottom - leg_a.body.bb.bottom,
        "halvings meet: both legs on the ground"
    assert leg_a.body.bb.width == 220 mm and leg_a.body.bb.height == 25 mm, "legs 220 x 25"
    assert leg_a.lighten.b.center.x == 82 mm and leg_a.lighten.b.length == 30 mm, "lightening slot"
    assert leg_a.lanyard.b.center.x == 103 mm and leg_a.lanyard.b.diameter == 4 mm, "lanyard hole"
    assert distance(leg_a.lanyard.b, leg_a.lighten.b) >= 2 mm, "wall between the holes"
}
