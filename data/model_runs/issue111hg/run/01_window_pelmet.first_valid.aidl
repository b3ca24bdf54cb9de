# Request (home): a box pelmet over a kitchen window, cut from 6 mm poplar ply.
# The front board is 612 mm wide and 160 mm high overall (the top board's 6 mm included),
# with a scalloped lower edge: five scallops, each 96 mm across and rising 25 mm, with
# 12 mm flats between them and 42 mm flats at each end. Two returns, 126 mm deep (front
# board included) and 160 mm high, finger-jointed to the front's ends (fingers at least
# 20 mm). A top board 624 x 132 mm that overhangs the front and the sides by 6 mm and is
# flush with the wall at the back; the front and the returns stand in it by glued tabs
# (three 60 mm tabs along the front, one 50 mm tab on each return). Four 5 mm holes,
# countersunk 10 mm, for two angle brackets to the wall at 220 mm either side of the centre,
# 25 mm and 55 mm in from the back edge. "FRONT" engraved on the top board's front edge.

import "std/joints.aidl"

units mm
thickness 6 mm

t = 6 mm
front_w = 612 mm
height = 160 mm
depth = 126 mm
top_w = 624 mm
top_d = 132 mm
scallop_w = 96 mm
scallop_rise = 25 mm
scallop_flat = 12 mm
scallops = 5
end_flat = (front_w - scallops * scallop_w - (scallops - 1) * scallop_flat) / 2
# radius of an arc spanning scallop_w and rising scallop_rise
scallop_r = (scallop_w ** 2 / 4 + scallop_rise ** 2) / (2 * scallop_rise)
joint_h = height - t

def pelmet_return() -> solid {
    body = Rectangle(center=(depth / 2, height / 2), width=depth, height=height)
    # the front edge (x = 0) mates the front board's finger edge
    fingers = finger_edge(length=joint_h, thickness=t, finger=20 mm, start="gap",
                          rotation=90 deg, cx=0 mm, cy=joint_h / 2)
    # one tab standing up into the top board
    tab = tab_and_slot(part="tab", length=depth, thickness=t, tabs=1, tab=50 mm, screw=0,
                       cx=depth / 2, cy=height)
}

assembly pelmet {
    solid front {
        body = Rectangle(center=(0, height / 2), width=front_w, height=height)
        left_fingers = finger_edge(length=joint_h, thickness=t, finger=20 mm, start="tab",
                                   rotation=90 deg, cx=-front_w / 2, cy=joint_h / 2)
        right_fingers = finger_edge(length=joint_h, thickness=t, finger=20 mm, start="tab",
                                    rotation=-90 deg, cx=front_w / 2, cy=joint_h / 2)
        tabs = tab_and_slot(part="tab", length=front_w, thickness=t, tabs=3, tab=60 mm,
                            screw=0, cx=0 mm, cy=height)
        hole scallop {
            c = Circle(center=(-front_w / 2 + end_flat + scallop_w / 2,
                               scallop_rise - scallop_r), radius=scallop_r)
        }
        sc = LinearPattern(scallop, scallops, (scallop_w + scallop_flat, 0))
    }

    ret_l = pelmet_return()
    ret_r = pelmet_return()

    solid top {
        body = Rectangle(center=(0, 0), width=top_w, height=top_d)
        # front board's tabs: its middle stands t + t/2 in from the top's front edge
        front_slots = tab_and_slot(part="slot", length=front_w, thickness=t, tabs=3,
                                   tab=60 mm, screw=0, clearance=0.1 mm,
                                   cx=0 mm, cy=-top_d / 2 + t + t / 2)
        # the returns: their outer faces flush with the front's ends, back edges at the wall
        left_slot = tab_and_slot(part="slot", length=depth, thickness=t, tabs=1, tab=50 mm,
                                 screw=0, clearance=0.1 mm, rotation=90 deg,
                                 cx=-front_w / 2 + t / 2, cy=top_d / 2 - depth / 2)
        right_slot = tab_and_slot(part="slot", length=depth, thickness=t, tabs=1, tab=50 mm,
                                  screw=0, clearance=0.1 mm, rotation=90 deg,
                                  cx=front_w / 2 - t / 2, cy=top_d / 2 - depth / 2)
        hole brackets {
            for i in range(4) {
                c = Circle(center=((-220 mm if i < 2 else 220 mm),
                                   top_d / 2 - (25 mm if i % 2 == 0 else 55 mm)), diameter=5)
            }
        }
        Countersink(brackets, diameter=10 mm)
        drawing label {
            word = Text("FRONT", (0, -top_d / 2 + 20 mm), size=8, valign="middle")
        }
    }

    Below(ret_l, front, gap=15)
    AlignLeft(ret_l, front)
    RightOf(ret_r, ret_l, gap=15)
    AlignTop(ret_r, ret_l)
    Above(top, front, gap=15)
    AlignCenterX(top, front)

    # the request's numbers
    assert front.body.bb.width == 612 mm, "front 612 wide"
    assert front.body.bb.height == 160 mm, "front 160 high overall"
    assert len(sc) == 5, "five scallops"
    assert sc[0].c.top.y - front.body.bb.bottom == 25 mm, "scallops rise 25"
    assert sc[0].c.center.x - front.body.bb.left == 42 mm + 48 mm, "42 mm end flat"
    assert sc[1].c.center.x - sc[0].c.center.x == 96 mm + 12 mm, "12 mm flats"
    assert ret_l.body.bb.width == 126 mm and ret_l.body.bb.height == 160 mm, "returns"
    assert top.body.bb.width == 624 mm and top.body.bb.height == 132 mm, "top board"
    assert top.brackets.c[2].center.x - top.body.bb.center_x == 220 mm, "brackets at 220"
    assert top.body.bb.top - top.brackets.c[1].center.y == 55 mm, "55 mm from the back"
}
