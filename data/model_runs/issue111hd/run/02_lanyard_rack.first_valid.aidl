# Request (office): "A visitor-lanyard rack for our reception desk wall, 4 mm ply.
# A wall plate 400 x 120 mm with VISITORS engraved (filled, bold, 18 mm capitals)
# across the top, four countersunk M4 screw holes 12 mm in from each corner, and a row
# of 8 hook pegs on 45 mm centres, 10 mm below the plate's middle, each numbered 1-8
# (engraved, 7 mm) 25 mm below its peg. Each peg stands 40 mm out from the wall,
# 15 mm tall, with a lip rising 10 mm above it at the tip so lanyards don't slide off,
# and is glued into the plate with one 10 mm tab through a mortise."

import "std/joints.aidl"
import "std/fasteners.aidl"

thickness 4 mm

T = 4 mm
n_pegs = 8
pitch = 45 mm
peg_y = -10 mm

def peg(x0=0 mm, y0=0 mm) -> solid {
    # side view: the wall face is x = x0, the arm runs out along +x
    arm = Rectangle(bottom_left=(x0, y0), width=40, height=15)
    lip = Rectangle(bottom_left=(x0 + 32, y0), width=8, height=25)
    root = Rectangle(bottom_left=(x0 - 4, y0), width=4, height=15)
    tab = tab_and_slot(part="tab", length=15 mm, thickness=4 mm, tabs=1, tab=10 mm,
                       screw=0, rotation=90 deg, cx=x0 - 4 mm, cy=y0 + 7.5 mm)
}

assembly lanyard_rack {
    solid plate {
        body = Rectangle(center=(0, 0), width=400, height=120)
        for i in range(n_pegs) {
            m = tab_and_slot(part="slot", length=15 mm, thickness=T, tabs=1, tab=10 mm,
                             screw=0, rotation=90 deg,
                             cx=(i - (n_pegs - 1) / 2) * pitch, cy=peg_y)
        }
        screw = clearance_hole(size=4, cx=-188 mm, cy=-48 mm)
        screws = CornerPattern(screw, body, inset=12)
        Countersink(screws, diameter=8.5)
        drawing title {
            t = Text("VISITORS", position=(0, 32), size=18, font="sans:Bold",
                     valign="middle", fill=true)
        }
        drawing numbers {
            for i in range(n_pegs) {
                n = Text(str(i + 1), position=((i - (n_pegs - 1) / 2) * pitch, peg_y - 25),
                         size=7, valign="middle")
            }
        }
    }

    for i in range(n_pegs) {
        p = peg(x0=-200 mm + i * 50 mm, y0=-110 mm)
    }

    assert plate.body.bb.width == 400 mm and plate.body.bb.height == 120 mm, "plate 400 x 120"
    assert len(p) == 8, "8 pegs"
    assert len(plate.m) == 8, "8 mortises"
    assert plate.m[1].slot[0].bb.center_x - plate.m[0].slot[0].bb.center_x == 45 mm, "45 mm centres"
    assert plate.body.bb.center_y - plate.m[0].slot[0].bb.center_y == 10 mm, "pegs 10 below the middle"
    assert p[0].arm.bb.width == 40 mm and p[0].arm.bb.height == 15 mm, "peg 40 out, 15 tall"
    assert p[0].lip.bb.top - p[0].arm.bb.top == 10 mm, "lip 10 above the arm"
    assert plate.m[0].slot[0].bb.center_y - plate.numbers.n[0].center.y == 25 mm, "numbers 25 below"
    assert screws[0].c.center.x - plate.body.bb.left == 12 mm, "screws 12 in"
    assert plate.body.bb.top - screws[2].c.center.y == 12 mm, "screws 12 in from the top"
}
