# Request (sport): "A wall rack for our four ice-hockey sticks, 6 mm ply, bolted
# together with M3 screws and captive nuts so it can be taken apart. A back plate
# 500 x 200 mm screwed to the wall with four countersunk M5 screws 15 mm in from the
# corners, HAWKS engraved filled (bold, 18 mm) 75 mm above the middle and the players'
# numbers 7, 19, 22, 91 (bold, 14 mm, filled) 45 mm above the middle, one over each
# stick. An arm 500 wide standing out 120 mm from the back, its centre line 20 mm above
# the back's middle, joined by 4 tabs 40 mm wide with screws between; in it four open
# fork slots 34 mm wide (a shaft is 30 x 20), 80 mm deep from the front edge, on 110 mm
# centres, their mouths rounded 5 mm. Two gussets under the arm, 220 mm either side of
# the middle, 100 mm down the back and 100 mm along the arm, each edge with 2 tabs
# 20 mm wide and a screw."

import "std/joints.aidl"
import "std/fasteners.aidl"

thickness 6 mm

T = 6 mm
W = 500 mm
arm_y = 20 mm
gus_x = 220 mm
leg = 100 mm
pitch = 110 mm
numbers = ["7", "19", "22", "91"]

def gusset(x0=0 mm, y0=0 mm) -> solid {
    # (x0, y0): where the back face meets the arm's underside
    web = Polygon([(x0, y0), (x0 + 100, y0), (x0, y0 - 100)])
    top_strip = Rectangle(bottom_left=(x0, y0), width=100, height=6)
    back_strip = Rectangle(bottom_left=(x0 - 6, y0 - 100), width=6, height=100)
    top_j = tab_and_slot(part="tab", length=100 mm, thickness=6 mm, tabs=2, tab=20 mm,
                         screw=3, cx=x0 + 50 mm, cy=y0 + 6 mm)
    back_j = tab_and_slot(part="tab", length=100 mm, thickness=6 mm, tabs=2, tab=20 mm,
                          screw=3, rotation=90 deg, cx=x0 - 6 mm, cy=y0 - 50 mm)
}

assembly stick_rack {
    solid back {
        body = Rectangle(center=(0, 0), width=W, height=200)
        arm_j = tab_and_slot(part="slot", length=W, thickness=T, tabs=4, tab=40 mm, screw=3,
                             cx=0 mm, cy=arm_y)
        gus_l = tab_and_slot(part="slot", length=leg, thickness=T, tabs=2, tab=20 mm, screw=3,
                             rotation=90 deg, cx=-gus_x, cy=arm_y - T / 2 - leg / 2)
        gus_r = tab_and_slot(part="slot", length=leg, thickness=T, tabs=2, tab=20 mm, screw=3,
                             rotation=90 deg, cx=gus_x, cy=arm_y - T / 2 - leg / 2)
        screw = clearance_hole(size=5, cx=-235 mm, cy=-85 mm)
        screws = CornerPattern(screw, body, inset=15)
        Countersink(screws, diameter=10)
        drawing team {
            t = Text("HAWKS", position=(0, 75), size=18, font="sans:Bold", valign="middle",
                     fill=true)
        }
        drawing nums {
            for i in range(4) {
                n = Text(numbers[i], position=((i - 1.5) * pitch, 45), size=14,
                         font="sans:Bold", valign="middle", fill=true)
            }
        }
    }

    solid arm {
        # back face of the back plate at y = -190, front edge at y = -310, tabs' tips at -184
        body = Rectangle(bottom_left=(-250, -310), width=W, height=126)
        j = tab_and_slot(part="tab", length=W, thickness=T, tabs=4, tab=40 mm, screw=3,
                         cx=0 mm, cy=-184 mm)
        gus_l = tab_and_slot(part="slot", length=leg, thickness=T, tabs=2, tab=20 mm, screw=3,
                             rotation=90 deg, cx=-gus_x, cy=-190 mm - leg / 2)
        gus_r = tab_and_slot(part="slot", length=leg, thickness=T, tabs=2, tab=20 mm, screw=3,
                             rotation=90 deg, cx=gus_x, cy=-190 mm - leg / 2)
        hole forks {
            for i in range(4) {
                u = Slot(start=((i - 1.5) * pitch, -330), end=((i - 1.5) * pitch, -247), width=34)
            }
        }
        for i in range(4) {
            Fillet([body, forks.u[i]], 5)
        }
    }

    left_gusset = gusset(x0=300 mm, y0=90 mm)
    right_gusset = gusset(x0=300 mm, y0=-30 mm)

    assert back.body.bb.width == 500 mm and back.body.bb.height == 200 mm, "back 500 x 200"
    assert screws[0].c.center.x - back.body.bb.left == 15 mm and screws[0].c.center.y - back.body.bb.bottom == 15 mm, "screws 15 in"
    assert back.team.t.center.y - back.body.bb.center_y == 75 mm, "HAWKS 75 above the middle"
    assert back.nums.n[0].center.y - back.body.bb.center_y == 45 mm, "numbers 45 above the middle"
    assert back.arm_j.slot[0].bb.center_y - back.body.bb.center_y == 20 mm, "arm 20 above the middle"
    assert arm.body.bb.height - 6 mm == 120 mm, "arm stands out 120"
    assert len(arm.forks.u) == 4 and arm.forks.u[0].width == 34 mm, "4 forks 34 wide"
    assert arm.forks.u[1].end.x - arm.forks.u[0].end.x == 110 mm, "110 centres"
    assert (arm.forks.u[0].end.y + 17 mm) - arm.body.bb.bottom == 80 mm, "forks 80 deep"
    assert back.nums.n[2].center.x == arm.forks.u[2].end.x, "numbers over the sticks"
    assert back.gus_r.slot[0].bb.center_x - back.body.bb.center_x == 220 mm or back.gus_r.bolt[0].c.center.x == 220 mm, "gussets 220 out"
    assert left_gusset.web.bb.width == 100 mm and left_gusset.web.bb.height == 100 mm, "gusset legs 100"
}
