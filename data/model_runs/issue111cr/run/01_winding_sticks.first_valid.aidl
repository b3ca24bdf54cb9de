# Request: a pair of winding sticks for checking a board for twist, cut from 6 mm birch ply.
# Each stick is 380 mm long and stands 45 mm tall on a 24 mm wide base strip (a T section, so
# the thin stick stands up by itself on the board), glued into the strip with 3 tabs 30 mm
# wide. The stick's top corners are chamfered 5 mm. A 6 mm hang hole 10 mm from the right end,
# at half the stick's height. Both sticks carry an engraved centre tick 10 mm long down from
# the top edge and their name ("FRONT" / "BACK") engraved 6 mm high in the middle; the back
# stick also has two 12 mm filled-engraved sight squares, 15 mm in from each end and 6 mm
# below the top edge. Four parts: front stick, front base, back stick, back base.

import "std/joints.aidl"

units mm
thickness 6 mm

param length = 380 mm, min = 250 mm, max = 500 mm
param rise = 45 mm, min = 35 mm, max = 70 mm
param base_w = 24 mm, min = 18 mm, max = 40 mm
T = 6 mm
TAB = 30 mm

def stick(label="FRONT", marks=false) -> solid {
    # the body reaches T below y = 0: the tabs that go through the base strip
    body = Rectangle(bottom_left=(-length / 2, -T), width=length, height=rise + T)
    joint = tab_and_slot(part="tab", length=length, thickness=T, tabs=3, tab=TAB, screw=0,
                         rotation=180 deg, cx=0 mm, cy=-T)
    hole hang { c = Circle(center=(length / 2 - 10 mm, rise / 2), diameter=6 mm) }
    drawing face {
        tick = Line((0, rise), (0, rise - 10 mm))
        name = Text(label, position=(0, rise / 2), size=6 mm, valign="middle")
        if marks {
            left_sq = Rectangle(center=(-length / 2 + 21 mm, rise - 12 mm), width=12 mm,
                                height=12 mm, fill=true)
            right_sq = Rectangle(center=(length / 2 - 21 mm, rise - 12 mm), width=12 mm,
                                 height=12 mm, fill=true)
        }
    }
    Chamfer([body.top_left, body.top_right], 5 mm)
}

def base_strip() -> solid {
    body = Rectangle(center=(0, 0), width=length, height=base_w)
    joint = tab_and_slot(part="slot", length=length, thickness=T, tabs=3, tab=TAB, screw=0,
                         cx=0 mm, cy=0 mm)
}

assembly winding_sticks {
    front_stick = stick(label="FRONT")
    front_base = base_strip()
    back_stick = stick(label="BACK", marks=true)
    back_base = base_strip()

    # flat on the sheet: one under the other
    Below(front_base, front_stick, gap=8 mm)
    AlignCenterX(front_base, front_stick)
    Below(back_stick, front_base, gap=8 mm)
    AlignCenterX(back_stick, front_base)
    Below(back_base, back_stick, gap=8 mm)
    AlignCenterX(back_base, back_stick)

    # in use: each stick stood in its base, the pair 300 mm apart on the board
    Place(front_base, position=(0, 0, 0))
    Place(front_stick, position=(0, T / 2, T), face="front", up="up")
    Place(back_base, position=(0, 300, 0))
    Place(back_stick, position=(0, 300 + T / 2, T), face="front", up="up")

    # the request's numbers
    assert front_stick.body.bb.width == 380 mm, "sticks 380 mm long"
    assert back_base.body.bb.width == 380 mm, "bases as long as the sticks"
    assert front_stick.body.bb.top - front_stick.joint.bb.top == 45 mm, "45 mm above the base"
    assert front_base.body.bb.height == 24 mm, "base strip 24 mm wide"
    assert len(front_stick.joint.gap) - 1 == 3, "3 tabs"
    assert front_stick.hang.c.diameter == 6 mm, "6 mm hang hole"
    assert front_stick.body.bb.right - front_stick.hang.c.center.x == 10 mm, "10 mm from the end"
    assert back_stick.face.left_sq.bb.width == 12 mm, "12 mm sight squares"
    assert back_stick.face.left_sq.bb.left - back_stick.body.bb.left == 15 mm, "15 mm in"
    assert back_stick.body.bb.right - back_stick.face.right_sq.bb.right == 15 mm, "15 mm in"
    assert back_stick.body.bb.top - back_stick.face.left_sq.bb.top == 6 mm, "6 mm below the top"
}
