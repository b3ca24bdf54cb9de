# Request: a cup-and-ball toy (bilboquet) in 6 mm plywood, for a 35 mm wooden bead on a string.
# The handle is two plates 30 mm wide and 160 mm long overall, crossed along their length by a
# cross halving (6 mm wide slots, 80 mm each: one plate slotted from the top, the other from the
# bottom); each plate's bottom end is a full R15 round, and its top is a 24 mm wide, 6 mm tall
# tenon. The tenons go into a cross-shaped mortise (two 24 x 6 mm openings crossed) in a 70 mm
# cup base disc; on the disc two 70 mm rings are glued, the lower with a 40 mm opening, the upper
# with a 48 mm one, so the ball sits in a stepped cup. A 4 mm hole for the string in the plate slotted
# from the top, 8 mm right of its middle line and 40 mm above its bottom end; "CUP AND BALL"
# engraved (5 mm letters, along the length) on the other plate's upper half, 9 mm right of its
# middle line, clear of the crossing plate.

import "std/joints.aidl"

thickness 6 mm

T = 6 mm
PLATE_W = 30 mm
PLATE_L = 160 mm
TENON_W = 24 mm
HALF = 80 mm
DISC = 70 mm

# a handle plate: its tenon's top on y = T, its round end at y = T - PLATE_L
def handle(from_top=true) -> solid {
    body = RoundedRectangle(center=(0, -(PLATE_L - T) / 2), width=PLATE_W, height=PLATE_L - T,
                            corner_radii=[0, 0, PLATE_W / 2, PLATE_W / 2])
    tenon = Rectangle(center=(0, T / 2), width=TENON_W, height=T)
    if from_top {
        halving = cross_halving(depth=HALF, thickness=T, cx=0 mm, cy=T)
        hole tie {
            c = Circle(center=(8 mm, T - PLATE_L + 40 mm), diameter=4 mm)
        }
    } else {
        halving = cross_halving(depth=HALF, thickness=T, rotation=180 deg, cx=0 mm, cy=T - PLATE_L)
        drawing label {
            t = Text("CUP AND BALL", position=(9 mm, T - HALF / 2), size=5 mm, rotation=90 deg,
                     valign="middle")
        }
    }
}

def cup_ring(opening=40 mm) -> solid {
    rim = Circle(center=(0, 0), diameter=DISC)
    hole bore {
        c = Circle(center=(0, 0), diameter=opening)
    }
}

assembly toy {
    plate_a = handle(from_top=true)
    plate_b = handle(from_top=false)

    solid base {
        disc = Circle(center=(0, 0), diameter=DISC)
        hole mortise {
            along_a = Rectangle(center=(0, 0), width=TENON_W, height=T)
            along_b = Rectangle(center=(0, 0), width=T, height=TENON_W)
        }
    }
    lower = cup_ring(opening=40 mm)
    upper = cup_ring(opening=48 mm)

    # flat on the sheet
    RightOf(plate_b, plate_a, gap=8 mm)
    AlignTop(plate_b, plate_a)
    RightOf(base, plate_b, gap=8 mm)
    AlignTop(base, plate_b)
    Below(lower, base, gap=8 mm)
    AlignLeft(lower, base)
    Below(upper, lower, gap=8 mm)
    AlignLeft(upper, lower)

    # in 3D: the cup on top (z = 0 its underside), the plates crossed below it
    Place(base, position=(0, 0, 0), face="up")
    Place(lower, position=(0, 0, T), face="up")
    Place(upper, position=(0, 0, 2 * T), face="up")
    Place(plate_a, position=(0, T / 2, 0), face="front", up="up")
    Place(plate_b, position=(-T / 2, 0, 0), face="right", up="up")

    assert plate_a.bb.height == 160 mm and plate_b.bb.height == 160 mm, "plates 160 long"
    assert plate_a.body.bb.width == 30 mm, "plates 30 wide"
    assert plate_a.tenon.bb.width == 24 mm and plate_a.tenon.bb.height == 6 mm, "tenon 24 x 6"
    assert plate_a.halving.cut.bb.width == 6 mm and plate_b.halving.cut.bb.width == 6 mm,
        "6 mm halving slots"
    assert plate_a.halving.cut.bb.height == 80 mm and plate_b.halving.cut.bb.height == 80 mm,
        "80 mm halving slots"
    assert plate_a.halving.cut.bb.top == plate_a.tenon.bb.top, "a slotted from the top"
    assert plate_b.halving.cut.bb.bottom == plate_b.body.bb.bottom, "b slotted from the bottom"
    assert base.disc.diameter == 70 mm and lower.rim.diameter == 70 mm and
        upper.rim.diameter == 70 mm, "70 mm cup"
    assert lower.bore.c.diameter == 40 mm and upper.bore.c.diameter == 48 mm, "stepped openings"
    assert base.mortise.along_a.bb.width == 24 mm and base.mortise.along_b.bb.height == 24 mm,
        "cross mortise 24 long"
    assert plate_a.tie.c.diameter == 4 mm, "4 mm string hole"
    assert plate_a.tie.c.center.x - plate_a.body.bb.center_x == 8 mm and
        plate_a.tie.c.center.y - plate_a.body.bb.bottom == 40 mm, "string hole 8 right, 40 up"
    assert distance(plate_a.tie, plate_a.halving) >= 2 mm, "string hole clear of the slot"
    assert plate_b.label.bb.left - plate_b.body.bb.center_x >= 3 mm + 1 mm,
        "label clear of the crossing plate"
    assert plate_b.label.bb.bottom >= plate_b.halving.cut.bb.top + 3 mm, "label on the upper half"
}
