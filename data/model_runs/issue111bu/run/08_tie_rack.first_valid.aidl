# Request (gifts): a personalised tie rack for my dad, 6 mm walnut-faced ply. A wall plate
# 350 mm wide, straight sides 70 mm tall and a gently arched top 90 mm tall at the middle,
# hung on two screws by keyholes (8 mm head, 4 mm slot, 10 mm long, upward) at (+-150, 55)
# from the plate's bottom middle. His initials "JM" engraved filled in a serif font, 22 mm,
# centred 60 mm up. A row of eight pegs 38 mm apart (centres), their middle 25 mm up: each
# peg reaches 60 mm out from the wall, is 12 mm tall, and ends in a 10 mm wide lip rising to
# 22 mm so the ties can't slide off; each has one 8 mm tenon glued through a mortise in the
# plate (tip flush with the back). All the peg's outside corners rounded r 2.

thickness 6 mm

import "std/joints.aidl"
import "std/plates.aidl"

W = 350 mm
SIDE_H = 70 mm
TOP_H = 90 mm
PEGS = 8
PEG_PITCH = 38 mm
PEG_Y = 25 mm           # the pegs' middle (of their 12 mm arm) above the plate's bottom
ARM_H = 12 mm
OUT = 60 mm
LIP_W = 10 mm
LIP_H = 22 mm
T = 6 mm

def peg() -> solid {
    # local frame: x = 0 is the wall (the tenon's tip), the arm along +x, y up
    arm = Rectangle(bottom_left=(0, 0), width=OUT, height=ARM_H)
    lip = Rectangle(bottom_left=(OUT - LIP_W, 0), width=LIP_W, height=LIP_H)
    tenon = tab_and_slot(part="tab", length=ARM_H, thickness=T, tabs=1, tab=8 mm, screw=0,
                         rotation=90 deg, cx=0 mm, cy=ARM_H / 2)
    Fillet([lip.top_left, lip.top_right, arm.bottom_right], 2)
}

def peg_x(i) = (i - (PEGS - 1) / 2) * PEG_PITCH

assembly tie_rack {
    solid plate {
        bottom = Line((-W / 2, 0), (W / 2, 0))
        right = Line((W / 2, 0), (W / 2, SIDE_H))
        top = Arc(start=(W / 2, SIDE_H), through=(0, TOP_H), end=(-W / 2, SIDE_H))
        left = Line((-W / 2, SIDE_H), (-W / 2, 0))
        hang_l = keyhole(head=8 mm, slot_width=4 mm, length=10 mm, direction=90 deg, cx=-150 mm, cy=55 mm)
        hang_r = keyhole(head=8 mm, slot_width=4 mm, length=10 mm, direction=90 deg, cx=150 mm, cy=55 mm)
        for i in range(PEGS) {
            mortise = tab_and_slot(part="slot", length=ARM_H, thickness=T, tabs=1, tab=8 mm,
                                   screw=0, rotation=90 deg, cx=peg_x(i), cy=PEG_Y)
        }
        drawing initials {
            t = Text("JM", position=(0, 60), size=22, font="serif", valign="middle", fill=true)
        }
    }
    for i in range(PEGS) {
        p = peg()
        # on the sheet: two rows of four under the plate
        p.bb.left == -W / 2 + (i % 4) * (OUT + 6 mm)
        p.bb.top == -8 mm - (i // 4) * (LIP_H + 6 mm)
        # assembled: standing out from the wall, its tenon through the plate
        Place(p, position=(peg_x(i) + T / 2, 0, PEG_Y - ARM_H / 2), rotation=(90 deg, 0, -90 deg))
    }
    Place(plate, position=(0, 0, 0), rotation=(90 deg, 0, 0))

    # the request's numbers
    assert len(p) == 8, "eight pegs"
    assert plate.mortise[1].slot[0].bb.center_x - plate.mortise[0].slot[0].bb.center_x == 38 mm, "38 apart"
    assert plate.mortise[0].slot[0].bb.center_y - plate.bottom.start.y == 25 mm, "pegs 25 up"
    assert p[0].arm.width == 60 mm, "60 mm out from the wall"
    assert p[0].lip.bb.top - p[0].arm.bb.bottom == 22 mm, "lip to 22 mm"
    assert plate.top.through.y - plate.bottom.start.y == 90 mm, "90 mm at the middle"
    assert plate.hang_l.slot.bb.top < plate.top.through.y - 10 mm, "keyhole inside the plate"
    assert plate.initials.t.size == 22 mm, "initials 22 mm"
}
