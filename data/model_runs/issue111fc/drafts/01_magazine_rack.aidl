# Request: a floor-standing magazine rack in 6 mm birch ply, glued, no screws.
# Two end panels 300 mm deep, 320 mm tall at the front and back edges and 380 mm at
# the middle (an arched top), with a 220 x 25 mm half-ellipse cut between the feet.
# Inside length between the end panels 400 mm. A bottom board 260 mm wide sits
# with its underside 40 mm off the floor, held by two 40 mm tenons through each
# end panel. A centre divider stands on the bottom board (three 40 mm tenons into
# it, two 40 mm tenons through each end panel up to 360 mm high) and rises to a
# 260 mm wide handle whose top is 440 mm off the floor, with a 110 x 32 mm
# hand-hold slot centred 405 mm up. Two 60 mm high lip rails along the front and
# back edges of the bottom board, one 30 mm tenon through each end panel.
# The family name "OKAFOR" engraved (filled serif, 28 mm capitals) on the outer
# face of both end panels, 250 mm up.
# FIX after the first valid program: the name moved to 200 mm up (at 250 it crossed the
# upper divider mortise, 260-300 mm: W0516), and the handle's lower corners made sharp
# (rounded ones left a small hooked notch where the handle meets the divider's body).

units mm
thickness 6 mm
import "std/joints.aidl"

T = 6 mm
L = 400 mm          # inside length between the end panels
D = 300 mm          # end panel depth
H_SIDE = 320 mm     # end panel height at front and back edges
H_MID = 380 mm      # end panel height at the middle
ZB = 40 mm          # underside of the bottom board above the floor
WB = 260 mm         # bottom board width
RAIL_H = 60 mm
JOINT_TOP = 360 mm  # divider's tenoned edge ends here
DIV_TOP = 440 mm
HANDLE_W = 260 mm

# an end panel, drawn as seen from outside: x across the depth, y up from the floor
def end_panel() -> solid {
    e1 = Line((-D / 2, 0), (D / 2, 0))
    e2 = Line((D / 2, 0), (D / 2, H_SIDE))
    e3 = Arc(start=(D / 2, H_SIDE), through=(0, H_MID), end=(-D / 2, H_SIDE))
    e4 = Line((-D / 2, H_SIDE), (-D / 2, 0))
    hole feet { arch = Ellipse(center=(0, 0), rx=110, ry=25) }
    board = tab_and_slot(part="slot", length=WB, thickness=T, tabs=2, tab=40 mm, screw=0,
                         cx=0 mm, cy=ZB + T / 2)
    divider = tab_and_slot(part="slot", length=JOINT_TOP - ZB, thickness=T, tabs=2, tab=40 mm,
                           screw=0, rotation=90 deg, cx=0 mm, cy=(ZB + JOINT_TOP) / 2)
    front_rail = tab_and_slot(part="slot", length=RAIL_H, thickness=T, tabs=1, tab=30 mm, screw=0,
                              rotation=90 deg, cx=-(WB / 2 - T / 2), cy=ZB + T + RAIL_H / 2)
    back_rail = tab_and_slot(part="slot", length=RAIL_H, thickness=T, tabs=1, tab=30 mm, screw=0,
                             rotation=90 deg, cx=WB / 2 - T / 2, cy=ZB + T + RAIL_H / 2)
    drawing name {
        t = Text("OKAFOR", position=(0, 200), size=28, font="serif:Bold", valign="middle", fill=true)
    }
}

# a lip rail, drawn from the front: x along the length, y up from the floor
def rail() -> solid {
    body = Rectangle(bottom_left=(-(L / 2 + T), ZB + T), width=L + 2 * T, height=RAIL_H)
    left_tenon = tab_and_slot(part="tab", length=RAIL_H, thickness=T, tabs=1, tab=30 mm, screw=0,
                              rotation=90 deg, cx=-(L / 2 + T), cy=ZB + T + RAIL_H / 2)
    right_tenon = tab_and_slot(part="tab", length=RAIL_H, thickness=T, tabs=1, tab=30 mm, screw=0,
                               rotation=-90 deg, cx=L / 2 + T, cy=ZB + T + RAIL_H / 2)
}

assembly magazine_rack {
    left_end = end_panel()
    right_end = end_panel()

    # bottom board, drawn from above: x along the length, y toward the back
    solid bottom {
        board = Rectangle(center=(0, 0), width=L + 2 * T, height=WB)
        left_tenons = tab_and_slot(part="tab", length=WB, thickness=T, tabs=2, tab=40 mm, screw=0,
                                   rotation=90 deg, cx=-(L / 2 + T), cy=0 mm)
        right_tenons = tab_and_slot(part="tab", length=WB, thickness=T, tabs=2, tab=40 mm, screw=0,
                                    rotation=-90 deg, cx=L / 2 + T, cy=0 mm)
        divider_mortises = tab_and_slot(part="slot", length=L, thickness=T, tabs=3, tab=40 mm,
                                        screw=0, cx=0 mm, cy=0 mm)
    }

    # centre divider, drawn from the front: x along the length, y up from the floor
    solid divider {
        lower = Rectangle(bottom_left=(-(L / 2 + T), ZB), width=L + 2 * T, height=JOINT_TOP - ZB)
        handle = RoundedRectangle(center=(0, DIV_TOP - 50), width=HANDLE_W, height=100,
                                  corner_radii=[30, 30, 0, 0])
        hole grip { s = Slot(center=(0, 405), length=110, width=32) }
        foot_tenons = tab_and_slot(part="tab", length=L, thickness=T, tabs=3, tab=40 mm, screw=0,
                                   rotation=180 deg, cx=0 mm, cy=ZB)
        left_tenons = tab_and_slot(part="tab", length=JOINT_TOP - ZB, thickness=T, tabs=2, tab=40 mm,
                                   screw=0, rotation=90 deg, cx=-(L / 2 + T), cy=(ZB + JOINT_TOP) / 2)
        right_tenons = tab_and_slot(part="tab", length=JOINT_TOP - ZB, thickness=T, tabs=2, tab=40 mm,
                                    screw=0, rotation=-90 deg, cx=L / 2 + T, cy=(ZB + JOINT_TOP) / 2)
    }

    front_rail = rail()
    back_rail = rail()

    # flat layout for cutting
    RightOf(right_end, left_end, gap=10)
    AlignBottom(right_end, left_end)
    Above(divider, left_end, gap=10)
    AlignLeft(divider, left_end)
    Above(bottom, divider, gap=10)
    AlignLeft(bottom, left_end)
    Above(front_rail, bottom, gap=10)
    AlignLeft(front_rail, left_end)
    Above(back_rail, front_rail, gap=10)
    AlignLeft(back_rail, left_end)

    # 3D: end panels face outward, the rest between them
    Place(left_end, position=(-L / 2, 0, 0), face="left", up="up")
    Place(right_end, position=(L / 2, 0, 0), face="right", up="up")
    Place(bottom, position=(0, 0, ZB), face="up")
    Place(divider, position=(0, T / 2, 0), face="front", up="up")
    Place(front_rail, position=(0, -WB / 2 + T, 0), face="front", up="up")
    Place(back_rail, position=(0, WB / 2 - T, 0), face="back", up="up")

    # the request's numbers
    assert left_end.e2.length == 320 mm, "end panel 320 mm tall at its edges"
    assert left_end.e1.length == 300 mm, "end panel 300 mm deep"
    assert left_end.e3.through.y - left_end.e1.start.y == 380 mm, "end panel 380 mm at the middle"
    assert bottom.board.height == 260 mm, "bottom board 260 mm wide"
    assert divider.handle.bb.top - divider.lower.bb.bottom == 440 mm - 40 mm, "handle top 440 mm off the floor"
    assert divider.grip.s.length == 110 mm and divider.grip.s.width == 32 mm, "hand-hold 110 x 32"
    assert front_rail.body.height == 60 mm, "rails 60 mm high"
    assert len(bottom.left_tenons.gap) == 3, "two tenons per end of the bottom board"
    assert len(divider.foot_tenons.gap) == 4, "three tenons under the divider"
}
