# Request: a toddler's pound-a-peg bench, 6 mm birch ply, five parts glued up.
# Top 240 x 100 mm, R8 corners, with four 20.5 mm holes for 20 mm dowel pegs, 54 mm apart
# in a row 8 mm behind the middle, each ringed by an engraved 30 mm circle, and the child's
# name "NOOR" engraved filled (bold, 12 mm) along the front. Two legs (end panels) 100 mm
# wide, 80 mm from the floor to the underside of the top, 105 mm either side of the middle,
# each with two 20 mm tenons through the top (0.2 mm clearance in the mortises) and an arch
# of radius 30 cut at the bottom so it stands on two feet. Front and back aprons 40 mm high,
# spanning the legs' outer faces (216 mm), flush with the legs' edges, finger-jointed to
# the legs (9 mm fingers).

import "std/joints.aidl"

thickness 6 mm
t = 6 mm

param pitch = 54 mm, min = 50 mm, max = 56 mm
peg_d = 20.5 mm
top_w = 240 mm
depth = 100 mm
leg_h = 80 mm
leg_x = 105 mm
apron_h = 40 mm
span = 2 * leg_x + t      # the legs' outer faces

def peg_x(i) = (i - 1.5) * pitch

def leg() -> solid {
    body = Rectangle(center=(0, (t - leg_h) / 2), width=depth, height=leg_h + t)
    tenons = tab_and_slot(part="tab", length=depth, thickness=t, tabs=2, tab=20, screw=0,
                          cx=0, cy=t)
    # the apron's middle finger goes into each side edge
    f_front = finger_edge(length=apron_h - 2 * t, thickness=t, finger=9, start="tab",
                          rotation=90, cx=-depth / 2, cy=-apron_h / 2)
    f_back = finger_edge(length=apron_h - 2 * t, thickness=t, finger=9, start="tab",
                         rotation=-90, cx=depth / 2, cy=-apron_h / 2)
    hole arch {
        a = Circle(center=(0, -leg_h), radius=30)
    }
}

def apron() -> solid {
    p = finger_panel(width=span, height=apron_h, thickness=t, finger=9, bottom="flat",
                     top="flat", left="slots", right="slots", cx=0, cy=-apron_h / 2)
}

assembly bench {
    solid top {
        board = RoundedRectangle(center=(0, 0), width=top_w, height=depth, corner_radius=8)
        hole pegs {
            for i in range(4) {
                p = Circle(center=(peg_x(i), 8), diameter=peg_d)
            }
        }
        m_left = tab_and_slot(part="slot", length=depth, thickness=t, tabs=2, tab=20, screw=0,
                              clearance=0.2, rotation=90, cx=-leg_x, cy=0)
        m_right = tab_and_slot(part="slot", length=depth, thickness=t, tabs=2, tab=20, screw=0,
                               clearance=0.2, rotation=90, cx=leg_x, cy=0)
        drawing deco {
            for i in range(4) {
                ring = Circle(center=(peg_x(i), 8), diameter=30)
            }
            name = Text("NOOR", position=(0, -32), size=12, font="sans:Bold", fill=true,
                        valign="middle")
        }
    }
    leg_l = leg()
    leg_r = leg()
    front = apron()
    back = apron()

    # on the sheet: legs under the top, aprons under the legs
    Below(leg_l, top, gap=6)
    AlignLeft(leg_l, top)
    RightOf(leg_r, leg_l, gap=6)
    AlignTop(leg_r, leg_l)
    Below(front, leg_l, gap=6)
    AlignLeft(front, top)
    Below(back, front, gap=6)
    AlignLeft(back, front)

    # in 3D (z up from the floor): top on the legs, legs at x = +-105, aprons front and back
    Place(top, position=(0, 0, leg_h), face="up")
    Place(leg_l, position=(-leg_x + t / 2, 0, leg_h), face="left", up="up")
    Place(leg_r, position=(leg_x + t / 2, 0, leg_h), face="left", up="up")
    Place(front, position=(0, -depth / 2 + t, leg_h), face="front", up="up")
    Place(back, position=(0, depth / 2 - t, leg_h), face="back", up="up")

    # the request's numbers
    assert top.board.width == 240 mm and top.board.height == 100 mm, "top 240 x 100"
    assert len(top.pegs.p) == 4, "four peg holes"
    assert top.pegs.p[0].diameter == 20.5 mm, "holes 20.5"
    assert top.pegs.p[1].center.x - top.pegs.p[0].center.x == 54 mm, "54 apart"
    assert top.pegs.p[0].center.y - top.board.center.y == 8 mm, "row 8 behind the middle"
    assert leg_l.body.width == 100 mm, "legs 100 wide"
    assert leg_l.body.height - t == 80 mm, "80 from the floor to the top's underside"
    assert top.m_right.slot[0].bb.center_x - top.board.center.x == 105 mm, "legs 105 out"
    assert front.p.outline.height == 40 mm and front.p.outline.width == 216 mm, "aprons 40 x 216"
    assert leg_l.arch.a.radius == 30 mm, "arch R30"
    assert distance(top.pegs, top.m_right) >= 5 mm, "holes clear of the mortises"
    assert distance(top.deco.name, top.deco.ring[0]) >= 2 mm, "name clear of the rings"
}
