# Request (parties): a tabletop roll-up ball game for a kids' party, played with ping-pong
# balls (40 mm). 3 mm ply, glued.
# - A lane 120 mm wide between two side walls, rising from the table 60 mm over 300 mm
#   (measured along the table), 290 mm long along its slope; then a target board 200 mm long
#   rising at 45 deg from the lane's top end, with three 46 mm holes on its centre line, 45,
#   105 and 165 mm up from its lower edge, scoring 10, 20 and 50 (numbers engraved beside each
#   hole, 12 mm, readable from the player's end). A ball that drops in falls to the table.
# - Two side walls 460 mm long whose top edge stands 40 mm above the lane and the target.
# - Lane and target held in mortises in the walls, two 20 mm tabs each side.
# - "SKEE-BALL" engraved across the lane near the player's end, 12 mm bold sans, and a foul line
#   20 mm from the lane's start.

import "std/joints.aidl"

thickness 3 mm
t = 3 mm

inner = 120 mm                  # lane width between the walls
lane_rise = 60 mm
lane_run = 300 mm
a = atan2(lane_rise, lane_run)  # the lane's slope
lane_len = 290 mm               # along the slope
target_len = 200 mm
b = 45 deg
wall_len = 460 mm
above = 40 mm

# profile (side view: x along the table, y up); the lane's top surface starts at (0, t)
lane_end = (lane_run, t + lane_rise)
tx0 = lane_run
ty0 = t + lane_rise

assembly skee_ball {
    def side_wall() -> solid {
        profile = Polygon([(0, 0), (wall_len, 0), (wall_len, above + ty0 + (wall_len - tx0)),
                           (tx0, ty0 + above), (0, t + above)])
        # the lane's mid-plane: 1.5 mm under its top surface, centred along its length
        lane_slots = tab_and_slot(part="slot", length=lane_len, thickness=t, tabs=2, tab=20,
                                  screw=0, rotation=a,
                                  cx=lane_len / 2 * cos(a) + t / 2 * sin(a),
                                  cy=t + lane_len / 2 * sin(a) - t / 2 * cos(a))
        target_slots = tab_and_slot(part="slot", length=target_len, thickness=t, tabs=2, tab=20,
                                    screw=0, rotation=b,
                                    cx=tx0 + target_len / 2 * cos(b) + t / 2 * sin(b),
                                    cy=ty0 + target_len / 2 * sin(b) - t / 2 * cos(b))
    }
    left_wall = side_wall()
    right_wall = side_wall()

    # the lane on the sheet: x along its slope (0 at the player's end), y across
    solid lane {
        body = Rectangle(bottom_left=(0, -inner / 2 - t), width=lane_len, height=inner + 2 * t)
        near = tab_and_slot(part="tab", length=lane_len, thickness=t, tabs=2, tab=20, screw=0,
                            rotation=0 deg, cx=lane_len / 2, cy=inner / 2 + t)
        far = tab_and_slot(part="tab", length=lane_len, thickness=t, tabs=2, tab=20, screw=0,
                           rotation=180 deg, cx=lane_len / 2, cy=-inner / 2 - t)
        drawing marks {
            word = Text("SKEE-BALL", position=(45, 0), size=12, font="sans:Bold", fill=true,
                        rotation=-90 deg, valign="middle")
            foul = Line((20, -inner / 2), (20, inner / 2))
        }
    }

    solid target {
        body = Rectangle(bottom_left=(0, -inner / 2 - t), width=target_len, height=inner + 2 * t)
        near = tab_and_slot(part="tab", length=target_len, thickness=t, tabs=2, tab=20, screw=0,
                            rotation=0 deg, cx=target_len / 2, cy=inner / 2 + t)
        far = tab_and_slot(part="tab", length=target_len, thickness=t, tabs=2, tab=20, screw=0,
                           rotation=180 deg, cx=target_len / 2, cy=-inner / 2 - t)
        hole cups {
            h10 = Circle(center=(45, 0), diameter=46)
            h20 = Circle(center=(105, 0), diameter=46)
            h50 = Circle(center=(165, 0), diameter=46)
        }
        drawing scores {
            s10 = Text("10", position=(45, -42), size=12, font="sans:Bold", fill=true,
                       rotation=-90 deg, valign="middle")
            s20 = Text("20", position=(105, -42), size=12, font="sans:Bold", fill=true,
                       rotation=-90 deg, valign="middle")
            s50 = Text("50", position=(165, -42), size=12, font="sans:Bold", fill=true,
                       rotation=-90 deg, valign="middle")
        }
    }

    # flat on the sheet
    Below(right_wall, left_wall, gap=5)
    AlignLeft(right_wall, left_wall)
    RightOf(lane, left_wall, gap=5)
    AlignTop(lane, left_wall)
    Below(target, lane, gap=5)
    AlignLeft(target, lane)

    # assembled: x across the lane, y away from the player, z up
    Place(left_wall, position=(-inner / 2 - t, 0, 0), face="right", up="up")
    Place(right_wall, position=(inner / 2, 0, 0), face="right", up="up")
    Place(lane, position=(0, t * sin(a), t - t * cos(a)), face=(0, -sin(a), cos(a)),
          up=(-1, 0, 0))
    Place(target, position=(0, tx0 + t * sin(b), ty0 - t * cos(b)), face=(0, -sin(b), cos(b)),
          up=(-1, 0, 0))

    assert lane.body.bb.height - 2 * t == 120 mm, "lane 120 wide"
    assert lane.body.bb.width == 290 mm, "lane 290 along its slope"
    assert target.body.bb.width == 200 mm, "target 200 long"
    assert target.cups.h10.diameter == 46 mm, "46 mm holes"
    assert target.cups.h20.center.x - target.cups.h10.center.x == 60 mm, "holes 60 apart"
    assert target.cups.h50.center.x - target.body.bb.left == 165 mm, "top hole 165 up"
    assert target.body.bb.right - target.cups.h50.center.x - 23 mm >= 8 mm, "rim above the top hole"
    assert left_wall.bb.width == 460 mm, "walls 460 long"
    assert distance(target.scores, target.cups) >= 2 mm, "numbers clear of the holes"
}
