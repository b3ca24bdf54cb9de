# Request: a tabletop Easter egg-rolling race for two children and their chocolate eggs (up to
# 35 mm across), 4 mm birch ply. A ramp board 400 mm long at 15 deg, two lanes 55 mm wide split
# by a 25 mm tall divider; its mid-line 6 mm above the table at the low end, where the eggs
# roll off. Two side panels carry the board in three 30 mm tenons on each edge and stand
# 35 mm above the board's mid-line as rails; each has two egg-shaped windows and "EASTER EGG
# ROLL" engraved filled, 8 mm tall, on its outside face. The divider is held by three 30 mm
# tenons into the board. A start gate 70 mm down the board from its high end drops into a
# notch in each side panel (4.4 mm wide, from the rail's top down to 15 mm above the board's
# mid-line) by two ears that stick 5 mm out past the panels; it clears the board by 1 mm, a
# slot from its bottom straddles the divider, a 40 x 14 finger slot lifts it, and "LIFT TO
# START" is engraved 5 mm tall on its front. Lane numbers "1" and "2" engraved 10 mm tall
# behind the gate, and a finish line 25 mm from the low end with "FINISH" 6 mm tall in each
# lane.

thickness 4 mm

import "std/joints.aidl"

T = 4 mm
a = 15 deg
Lb = 400 mm
run = Lb * cos(a)
rise = Lb * sin(a)
lane = 55 mm
inner = 2 * lane + T          # between the side panels
h0 = 6 mm                     # the board's mid-line above the table at the low end
h_mid = h0 + rise / 2
rail = 35 mm
xg = Lb / 2 - 70 mm           # the gate, along the board from its centre
yg = xg * cos(a)              # ... and along the table

def hm(x) = h0 + (x + run / 2) * tan(a)

# a side panel; hand = 1: the high end toward +x (seen from outside: the right panel),
# hand = -1: its mirror image (the left panel)
def side(hand=1) -> solid {
    body = Polygon([(-hand * run / 2, 0), (hand * run / 2, 0),
                    (hand * run / 2, hm(run / 2) + rail), (-hand * run / 2, hm(-run / 2) + rail)])
    ramp = tab_and_slot(part="slot", length=Lb, thickness=T, tabs=3, tab=30 mm, screw=0,
                        rotation=hand * a, cx=0, cy=h_mid)
    hole gate_notch {
        n = Rectangle(corner=(hand * yg - (T + 0.4 mm) / 2, hm(yg) + 15 mm),
                      opposite=(hand * yg + (T + 0.4 mm) / 2, hm(yg) + rail + 6 mm), overrun=true)
    }
    hole eggs {
        for ex in [50 mm, 125 mm] {
            e = Hull(Circle(center=(hand * ex, 22), radius=12), Circle(center=(hand * ex, 37), radius=8))
        }
    }
    drawing label {
        t = Text("EASTER EGG ROLL", position=(-hand * 40 mm, 12), size=8, font="sans:Bold",
                 fill=true)
    }
}

assembly egg_roll {
    side_r = side(hand=1)
    side_l = side(hand=-1)

    solid board {
        body = Rectangle(center=(0, 0), width=Lb, height=inner + 2 * T)
        edge_1 = tab_and_slot(part="tab", length=Lb, thickness=T, tabs=3, tab=30 mm, screw=0,
                              cx=0, cy=inner / 2 + T)
        edge_2 = tab_and_slot(part="tab", length=Lb, thickness=T, tabs=3, tab=30 mm, screw=0,
                              rotation=180 deg, cx=0, cy=-(inner / 2 + T))
        mort = tab_and_slot(part="slot", length=Lb, thickness=T, tabs=3, tab=30 mm, screw=0,
                            cx=0, cy=0)
        # drawing +x runs up the ramp, +y to the left seen from the low end
        drawing marks {
            n1 = Text("1", position=(Lb / 2 - 30 mm, (lane + T) / 2), size=10, rotation=-90 deg,
                      valign="middle")
            n2 = Text("2", position=(Lb / 2 - 30 mm, -(lane + T) / 2), size=10, rotation=-90 deg,
                      valign="middle")
            f1 = Line((-Lb / 2 + 25 mm, T / 2 + 3 mm), (-Lb / 2 + 25 mm, inner / 2 - 3 mm))
            f2 = Line((-Lb / 2 + 25 mm, -T / 2 - 3 mm), (-Lb / 2 + 25 mm, -inner / 2 + 3 mm))
            w1 = Text("FINISH", position=(-Lb / 2 + 12 mm, (lane + T) / 2), size=6,
                      rotation=-90 deg, valign="middle")
            w2 = Text("FINISH", position=(-Lb / 2 + 12 mm, -(lane + T) / 2), size=6,
                      rotation=-90 deg, valign="middle")
        }
    }

    solid divider {
        body = Rectangle(corner=(-Lb / 2, -T), opposite=(Lb / 2, 25))
        feet = tab_and_slot(part="tab", length=Lb, thickness=T, tabs=3, tab=30 mm, screw=0,
                            rotation=180 deg, cx=0, cy=-T)
    }

    solid gate {
        body = Rectangle(corner=(-(inner / 2 - 0.5 mm), 1), opposite=(inner / 2 - 0.5 mm, 60))
        ears = Rectangle(corner=(-(inner / 2 + T + 5 mm), 13), opposite=(inner / 2 + T + 5 mm, 40))
        straddle = cross_halving(depth=27 mm, thickness=T, clearance=0.4 mm, rotation=180 deg,
                                 cx=0, cy=1)
        hole grip {
            s = Slot(center=(0, 49), length=40, width=14)
        }
        drawing word {
            t = Text("LIFT TO START", position=(0, 34), size=5, valign="middle")
        }
    }

    # flat on the sheet
    Below(side_l, side_r, gap=8)
    AlignLeft(side_l, side_r)
    Below(board, side_l, gap=8)
    AlignLeft(board, side_l)
    Below(divider, board, gap=8)
    AlignLeft(divider, board)
    RightOf(gate, side_r, gap=8)
    AlignTop(gate, side_r)

    # in 3D: the ramp rises toward +y, the eggs roll toward the viewer (-y)
    Place(side_r, position=(inner / 2, 0, 0), face="right", up="up")
    Place(side_l, position=(-inner / 2, 0, 0), face="left", up="up")
    Place(board, face=(0, -sin(a), cos(a)), up="left",
          position=(0, T / 2 * sin(a), h_mid - T / 2 * cos(a)))
    Place(divider, face="right", up=(0, -sin(a), cos(a)),
          position=(-T / 2, -T / 2 * sin(a), h_mid + T / 2 * cos(a)))
    Place(gate, face="front", up="up", position=(0, yg + T / 2, hm(yg) + T / 2 / cos(a)))

    # the request's numbers
    assert board.body.width == 400 mm, "board 400 long"
    assert board.body.height - 2 * T == 2 * 55 mm + T, "two 55 mm lanes and the divider"
    assert abs(atan2(side_r.body.points[2].y - side_r.body.points[3].y,
                     side_r.body.points[2].x - side_r.body.points[3].x) - 15 deg) < 0.01 deg,
        "15 deg slope"
    assert side_r.body.points[3].y - 6 mm == 35 mm, "rails 35 above the mid-line"
    assert side_r.ramp.slot[0].bb.center_y - side_r.body.bb.bottom > 0, "slots in the panel"
    assert divider.body.height - T == 25 mm, "divider 25 tall"
    assert len(board.edge_1.gap) == 4 and len(divider.feet.gap) == 4, "three tenons"
    assert side_r.gate_notch.n.center.x == (400 mm / 2 - 70 mm) * cos(15 deg), "gate 70 down"
    assert side_r.gate_notch.n.width == 4.4 mm, "notch 4.4 wide"
    assert gate.ears.bb.right - (gate.body.bb.right + 0.5 mm + T) == 5 mm, "ears 5 mm out"
    assert gate.straddle.cut.bb.top - gate.body.bb.bottom >= 25 mm + 1 mm, "gate clears divider"
    assert gate.grip.s.length == 40 mm and gate.grip.s.width == 14 mm, "40 x 14 finger slot"
    assert lane >= 35 mm + 10 mm, "a 35 mm egg rolls free in its lane"
    assert distance(side_r.label, side_r.ramp) >= 3 mm, "label clear of the slots"
    assert distance(side_r.label, side_r.eggs) >= 3 mm, "label clear of the windows"
    assert distance(side_r.eggs, side_r.ramp) >= 3 mm, "windows clear of the slots"
    assert distance(board.marks, board.mort) >= 2 mm, "marks clear of the divider's slots"
    assert board.marks.n1.size == 10 mm and board.marks.w1.size == 6 mm, "text sizes"
    assert side_r.label.t.size == 8 mm and gate.word.t.size == 5 mm, "text sizes"
    assert board.marks.f1.start.x - board.body.bb.left == 25 mm, "finish 25 from the low end"
}
