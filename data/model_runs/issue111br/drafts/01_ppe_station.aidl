# Request: a wall-mounted PPE station for the workshop door, cut from 6 mm plywood.
# A 300 x 220 mm back plate with 10 mm rounded corners, screwed to the wall by four
# 4.5 mm holes 15 mm in from each corner, countersunk 9 mm for M4 flat heads. "PPE" engraved
# (filled, bold, 30 mm tall) across the top. On the left, a hook arm for ear defenders:
# it reaches 110 mm out from the plate's face, its top bar 20 mm deep with a 20 mm lip that
# rises 20 mm above the bar at the end, braced diagonally, and joins the plate with two 15 mm
# glued tabs along its 80 mm wall edge. On the right, a 150 x 80 mm shelf for safety glasses
# (three 10 mm slots 45 mm deep from the front edge, 45 mm apart, one pair hanging by a
# temple arm in each), glued to the plate with three 20 mm tabs and carried by two triangular
# 70 mm tall brackets, each with two 12 mm tabs into the plate. Labels "EAR DEFENDERS" and
# "SAFETY GLASSES" engraved 7 mm under each.

units mm
thickness 6 mm

import "std/joints.aidl"

T = 6 mm
ARM_X = -90 mm          # middle of the hook arm's thickness, on the back plate
ARM_EDGE = 80 mm        # the arm's wall edge (tabbed)
ARM_MID_Y = -10 mm      # the middle of that edge, in back-plate coordinates
SHELF_X = 60 mm         # the shelf's centre line on the back plate
SHELF_W = 150 mm
SHELF_D = 80 mm
SHELF_Y = -10 mm        # the shelf's underside, in back-plate coordinates
BR_H = 70 mm            # bracket height at the wall
BR_INSET = 13 mm        # bracket middle, in from the shelf's end

# a triangular bracket drawn in wall coordinates: x out from the plate face, y up
def bracket(top_y=0 mm) -> solid {
    body = Polygon([(-T, top_y - BR_H), (-T, top_y), (SHELF_D, top_y), (SHELF_D, top_y - 8),
                    (6, top_y - BR_H)])
    tabs = tab_and_slot(part="tab", length=BR_H, thickness=T, tabs=2, tab=12 mm, screw=0,
                        rotation=90 deg, cx=-T, cy=top_y - BR_H / 2)
}

assembly ppe_station {
    solid back {
        plate = RoundedRectangle(center=(0, 0), width=300, height=220, corner_radius=10)
        hole screw { c = Circle(center=(-135, -95), diameter=4.5) }
        screws = CornerPattern(screw, plate, inset=15)
        Countersink(screws, diameter=9 mm)
        arm_slots = tab_and_slot(part="slot", length=ARM_EDGE, thickness=T, tabs=2, tab=15 mm,
                                 screw=0, clearance=0.1 mm, rotation=90 deg,
                                 cx=ARM_X, cy=ARM_MID_Y)
        shelf_slots = tab_and_slot(part="slot", length=SHELF_W, thickness=T, tabs=3,
                                   tab=20 mm, screw=0, clearance=0.1 mm,
                                   cx=SHELF_X, cy=SHELF_Y + T / 2)
        left_br_slots = tab_and_slot(part="slot", length=BR_H, thickness=T, tabs=2, tab=12 mm,
                                     screw=0, clearance=0.1 mm, rotation=90 deg,
                                     cx=SHELF_X - SHELF_W / 2 + BR_INSET,
                                     cy=SHELF_Y - BR_H / 2)
        right_br_slots = tab_and_slot(part="slot", length=BR_H, thickness=T, tabs=2, tab=12 mm,
                                      screw=0, clearance=0.1 mm, rotation=90 deg,
                                      cx=SHELF_X + SHELF_W / 2 - BR_INSET,
                                      cy=SHELF_Y - BR_H / 2)
        drawing title {
            t = Text("PPE", position=(0, 80), size=30, font="sans:Bold", valign="middle",
                     fill=true)
        }
        drawing ear_label {
            t = Text("EAR DEFENDERS", position=(ARM_X, -75), size=7, valign="middle")
        }
        drawing eye_label {
            t = Text("SAFETY GLASSES", position=(SHELF_X, -95), size=7, valign="middle")
        }
    }

    # the hook arm, drawn in wall coordinates: x out from the plate face, y as on the plate
    solid arm {
        body = Polygon([(-T, ARM_MID_Y - 40), (-T, ARM_MID_Y + 40), (90, ARM_MID_Y + 40),
                        (90, ARM_MID_Y + 60), (110, ARM_MID_Y + 60), (110, ARM_MID_Y + 20),
                        (70, ARM_MID_Y + 20), (10, ARM_MID_Y - 40)])
        tabs = tab_and_slot(part="tab", length=ARM_EDGE, thickness=T, tabs=2, tab=15 mm,
                            screw=0, rotation=90 deg, cx=-T, cy=ARM_MID_Y)
        Fillet([body.points[3], body.points[4], body.points[5]], 4)
    }

    # the glasses shelf, drawn as seen from above: x along the wall, y toward the wall
    solid shelf {
        board = Rectangle(center=(SHELF_X, -SHELF_D / 2 - T / 2), width=SHELF_W,
                          height=SHELF_D + T)
        tabs = tab_and_slot(part="tab", length=SHELF_W, thickness=T, tabs=3, tab=20 mm,
                            screw=0, cx=SHELF_X, cy=0)
        hole slots {
            for i in range(3) {
                s = Rectangle(center=(SHELF_X + (i - 1) * 45, -T - SHELF_D + 45 / 2 - 1),
                              width=10, height=47)
            }
        }
    }

    left_bracket = bracket(top_y=SHELF_Y)
    right_bracket = bracket(top_y=SHELF_Y)

    # 3D: the back plate upright, its back face on the wall (y = 0), the rest sticking out to -y
    Place(back, rotation=(90 deg, 0, 0), position=(0, 0, 0))
    Place(arm, rotation=(90 deg, 0, -90 deg), position=(ARM_X + T / 2, -T, 0))
    Place(shelf, position=(0, 0, SHELF_Y))
    Place(left_bracket, rotation=(90 deg, 0, -90 deg),
          position=(SHELF_X - SHELF_W / 2 + BR_INSET + T / 2, -T, 0))
    Place(right_bracket, rotation=(90 deg, 0, -90 deg),
          position=(SHELF_X + SHELF_W / 2 - BR_INSET + T / 2, -T, 0))

    # the sheet: parts side by side
    RightOf(arm, back, gap=10)
    Below(shelf, back, gap=10)
    RightOf(left_bracket, arm, gap=10)
    Below(right_bracket, left_bracket, gap=10)
    AlignLeft(right_bracket, left_bracket)

    # the request's numbers
    assert back.plate.bb.width == 300 mm and back.plate.bb.height == 220 mm, "back plate 300 x 220"
    assert arm.body.bb.width - T == 110 mm, "hook reaches 110 mm out from the plate face"
    assert shelf.board.bb.width == 150 mm, "shelf 150 wide"
    assert shelf.board.bb.height - T == 80 mm, "shelf 80 deep"
    assert len(shelf.slots.s) == 3, "three glasses slots"
    assert shelf.slots.s[0].bb.top - shelf.board.bb.bottom == 45 mm, "slots 45 deep"
    assert left_bracket.body.bb.height == 70 mm, "brackets 70 tall"
}
