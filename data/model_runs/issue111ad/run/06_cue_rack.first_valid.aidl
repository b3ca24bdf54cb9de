# Sport: the top half of a wall rack for six pool cues at my club, 3 mm plywood
# (the butts stand on the floor). Back plate 480 x 100 mm, corners R8, hung on
# two keyholes (8 mm head, 4 mm slot 10 mm up) 210 mm either side of the middle,
# 15 mm below the plate's centre. A rack arm 480 x 70 mm sticks out square from
# the back, its middle plane 20 mm below the back's top edge, glued in by 3 tabs
# 40 mm wide; six U-notches for the cue shafts open at its front edge, 16 mm wide
# and 35 mm deep with round bottoms, 75 mm apart, centred. Two right-triangle
# gussets (60 along the back, 60 under the arm) 150 mm either side of the middle,
# each glued by one 20 mm tab into the back and one into the arm.
# "8-BALL CLUB" filled bold sans letters 14 mm high engraved on the back, centred
# 15 mm below the plate's centre.

import "std/joints.aidl"
import "std/plates.aidl"

units mm
thickness 3 mm

param t = 3 mm, min = 2, max = 6
param length = 480 mm, min = 300, max = 600
param cues = 6, min = 2, max = 7
param pitch = 75 mm, min = 50, max = 90
param notch_w = 16 mm, min = 12, max = 22
param notch_d = 35 mm, min = 20, max = 50
param arm_d = 70 mm, min = 50, max = 90
param gusset = 60 mm, min = 40, max = 70
param gusset_x = 150 mm, min = 100, max = 200

def gusset_plate(size=60 mm, t=3 mm) -> solid {
    body = Polygon([(0, 0), (size, 0), (0, -size)])
    # tab into the back plate along the vertical edge, tab into the arm along the top edge
    to_back = tab_and_slot(part="tab", length=size, thickness=t, tabs=1, tab=20 mm, screw=0,
                           rotation=90 deg, cx=0 mm, cy=-size / 2)
    to_arm = tab_and_slot(part="tab", length=size, thickness=t, tabs=1, tab=20 mm, screw=0,
                          cx=size / 2, cy=0 mm)
}

assembly cue_rack {
    solid back {
        plate = RoundedRectangle(center=(0, 0), width=length, height=100, corner_radius=8)
        hang_l = keyhole(head=8 mm, slot_width=4 mm, length=10 mm, cx=-210 mm, cy=-15 mm)
        hang_r = keyhole(head=8 mm, slot_width=4 mm, length=10 mm, cx=210 mm, cy=-15 mm)
        arm_slots = tab_and_slot(part="slot", length=length, thickness=t, tabs=3, tab=40 mm,
                                 screw=0, cx=0 mm, cy=30 mm)
        # a gusset's vertical edge runs from the arm's top face (31.5) down `gusset`
        g_l = tab_and_slot(part="slot", length=gusset, thickness=t, tabs=1, tab=20 mm,
                           screw=0, rotation=90 deg, cx=-gusset_x, cy=30 mm + t / 2 - gusset / 2)
        g_r = tab_and_slot(part="slot", length=gusset, thickness=t, tabs=1, tab=20 mm,
                           screw=0, rotation=90 deg, cx=gusset_x, cy=30 mm + t / 2 - gusset / 2)
        drawing name {
            word = Text("8-BALL CLUB", position=(0, -15), size=14, valign="middle",
                        font="sans:Bold", fill=true)
        }
        assert plate.bb.top - arm_slots.bb.center_y == 20 mm, "arm 20 below the top edge"
        assert (hang_r.head_hole.center.x == 210 mm
                and hang_r.head_hole.center.y == -15 mm), "keyholes 210 out, 15 below the centre"
    }

    solid arm {
        board = Rectangle(center=(0, 0), width=length, height=arm_d)
        into_back = tab_and_slot(part="tab", length=length, thickness=t, tabs=3, tab=40 mm,
                                 screw=0, cx=0 mm, cy=arm_d / 2)
        hole notches {
            for i in range(cues) {
                n = Slot(start=(-(cues - 1) * pitch / 2 + i * pitch, -arm_d / 2),
                         end=(-(cues - 1) * pitch / 2 + i * pitch, -arm_d / 2 + notch_d - notch_w / 2),
                         width=notch_w)
            }
        }
        # the gussets' tabs: their middle 30 from the back face (the tabs' tips)
        g_l = tab_and_slot(part="slot", length=gusset, thickness=t, tabs=1, tab=20 mm,
                           screw=0, rotation=90 deg, cx=-gusset_x, cy=arm_d / 2 - gusset / 2)
        g_r = tab_and_slot(part="slot", length=gusset, thickness=t, tabs=1, tab=20 mm,
                           screw=0, rotation=90 deg, cx=gusset_x, cy=arm_d / 2 - gusset / 2)
        assert len(notches.n) == 6, "six cues"
        assert notches.n[1].start.x - notches.n[0].start.x == 75 mm, "75 apart"
        assert notches.n[0].width == 16 mm, "notches 16 wide"
        assert notches.n[0].end.y + notch_w / 2 - board.bb.bottom == 35 mm, "notches 35 deep"
        assert board.bb.height == 70 mm, "arm 70 deep"
    }

    gusset_l = gusset_plate(size=gusset, t=t)
    gusset_r = gusset_plate(size=gusset, t=t)

    Below(arm, back, gap=10)
    AlignCenterX(arm, back)
    RightOf(gusset_l, back, gap=10)
    AlignTop(gusset_l, back)
    Below(gusset_r, gusset_l, gap=10)
    AlignLeft(gusset_r, gusset_l)

    assert back.plate.bb.width == 480 mm and back.plate.bb.height == 100 mm, "back 480 x 100"
    assert arm.board.bb.width == 480 mm, "arm 480 long"
}
