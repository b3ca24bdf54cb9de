# Request: a mini basketball hoop that hangs over a bedroom door, for a 12 cm foam ball,
# from 6 mm ply. Backboard 300 x 200 mm, 10 mm rounded corners, with the shooting box
# engraved as a filled 4 mm band round a 120 x 90 mm rectangle whose bottom edge is level
# with the rim's top, and "HOOPS" engraved filled in bold, 16 mm high, centred 80 mm above the
# board's centre. Rim: a ring of 150 mm inside diameter, 12 mm wide, its top 30 mm below the
# board's centre, standing 10 mm clear of the board on an 80 mm wide neck glued into the board
# with two 20 mm tabs; 10 net notches (3 mm wide, 5 mm deep) 30 deg apart round the front of
# the ring. Two triangle gussets (32 mm out, 66 mm down) under the neck, 30 mm either side of
# the middle, tabbed into board and ring. Two J hooks 100 mm either side of the middle,
# tabbed (two 15 mm tabs) into the board's back over its top 60 mm, reach over a 40 mm door
# with 4 mm play: 15 mm legs and bar, the bar's underside 15 mm above the board's top, the
# back leg 40 mm long.

import "std/joints.aidl"

thickness 6 mm

T = 6 mm
RING_IN = 150 mm
RING_W = 12 mm
R_OUT = RING_IN / 2 + RING_W
STANDOFF = 10 mm
RIM_TOP = -30 mm                      # the rim's top, from the board's centre
RING_CY = -T - STANDOFF - R_OUT       # the ring's centre, from the board's back face (y = 0)
DOOR = 40 mm
PLAY = 4 mm

def gusset() -> solid {
    # u: out from the board's front face (u = -6 .. 0: the tabs in the board);
    # v: up, as on the board (its top edge under the ring at v = RIM_TOP - T)
    body = Polygon([(-T, RIM_TOP), (26, RIM_TOP), (-T, RIM_TOP - T - 60)])
    to_ring = tab_and_slot(part="tab", length=32 mm, thickness=T, tabs=1, tab=12 mm, screw=0,
                           cx=10 mm, cy=RIM_TOP)
    to_board = tab_and_slot(part="tab", length=66 mm, thickness=T, tabs=1, tab=24 mm, screw=0,
                            rotation=90 deg, cx=-T, cy=RIM_TOP - 33 mm)
}

def hook() -> solid {
    # u: back from the board's back face (the door side), v: up, as on the board (top at 100)
    front_leg = Rectangle(bottom_left=(0, 40), width=15, height=90)
    bar = Rectangle(bottom_left=(0, 115), width=15 + DOOR + PLAY + 15, height=15)
    back_leg = Rectangle(bottom_left=(15 + DOOR + PLAY, 115 - 40 + 15), width=15, height=40)
    strip = Rectangle(bottom_left=(-T, 40), width=T, height=60)
    to_board = tab_and_slot(part="tab", length=60 mm, thickness=T, tabs=2, tab=15 mm, screw=0,
                            rotation=90 deg, cx=-T, cy=70 mm)
    Fillet([front_leg, bar, back_leg], 8)
}

assembly hoop {
    solid board {
        body = RoundedRectangle(center=(0, 0), width=300, height=200, corner_radius=10)
        neck_slots = tab_and_slot(part="slot", length=80 mm, thickness=T, tabs=2, tab=20 mm,
                                  screw=0, cx=0 mm, cy=RIM_TOP - T / 2)
        left_gusset_slot = tab_and_slot(part="slot", length=66 mm, thickness=T, tabs=1,
                                        tab=24 mm, screw=0, rotation=90 deg, cx=-30 mm,
                                        cy=RIM_TOP - 33 mm)
        right_gusset_slot = tab_and_slot(part="slot", length=66 mm, thickness=T, tabs=1,
                                         tab=24 mm, screw=0, rotation=90 deg, cx=30 mm,
                                         cy=RIM_TOP - 33 mm)
        left_hook_slots = tab_and_slot(part="slot", length=60 mm, thickness=T, tabs=2, tab=15 mm,
                                       screw=0, rotation=90 deg, cx=-100 mm, cy=70 mm)
        right_hook_slots = tab_and_slot(part="slot", length=60 mm, thickness=T, tabs=2,
                                        tab=15 mm, screw=0, rotation=90 deg, cx=100 mm, cy=70 mm)
        drawing marks {
            # the band inside the box's outline, 2 mm clear of the neck's slots under it
            target = Rectangle(bottom_left=(-60, RIM_TOP + 2), width=120, height=90,
                               construction=true)
            band = Shell(target, -4, join="miter", fill=true)
            word = Text("HOOPS", position=(0, 80), size=16, font="sans:Bold", valign="middle",
                        fill=true)
        }
    }

    solid ring {
        # drawn as seen from above: x across, y = 0 the board's back face, the ring toward -y
        outer = Circle(center=(0, RING_CY), radius=R_OUT)
        neck = Rectangle(bottom_left=(-40, -30), width=80, height=30)
        to_board = tab_and_slot(part="tab", length=80 mm, thickness=T, tabs=2, tab=20 mm,
                                screw=0, cx=0 mm, cy=0 mm)
        hole opening { c = Circle(center=(0, RING_CY), diameter=RING_IN) }
        hole net {
            for i in range(10) {
                s = Slot(center=(R_OUT * cos(135 deg + i * 30 deg),
                                 RING_CY + R_OUT * sin(135 deg + i * 30 deg)),
                         length=10, width=3, rotation=135 deg + i * 30 deg)
            }
        }
        left_gusset_slot = tab_and_slot(part="slot", length=32 mm, thickness=T, tabs=1, tab=12 mm,
                                        screw=0, rotation=90 deg, cx=-30 mm, cy=-T - 10 mm)
        right_gusset_slot = tab_and_slot(part="slot", length=32 mm, thickness=T, tabs=1,
                                         tab=12 mm, screw=0, rotation=90 deg, cx=30 mm,
                                         cy=-T - 10 mm)
    }

    left_gusset = gusset()
    right_gusset = gusset()
    left_hook = hook()
    right_hook = hook()

    # 3D: the board's back face on the door at y = 0, its front toward -y; z as on the board
    Place(board, rotation=(90 deg, 0, 0), position=(0, 0, 0))
    Place(ring, position=(0, 0, RIM_TOP - T))
    # (u, v, w) -> (-w, -u - 6, v): the gussets under the neck, their middles at x = -30, 30
    Place(left_gusset, rotation=(90 deg, 0, -90 deg), position=(-30 + T / 2, -T, 0))
    Place(right_gusset, rotation=(90 deg, 0, -90 deg), position=(30 + T / 2, -T, 0))
    # (u, v, w) -> (w, u, v): the hooks behind the board, their middles at x = -100, 100
    Place(left_hook, rotation=(90 deg, 0, 90 deg), position=(-100 - T / 2, 0, 0))
    Place(right_hook, rotation=(90 deg, 0, 90 deg), position=(100 - T / 2, 0, 0))

    # on the sheet
    RightOf(ring, board, gap=8)
    AlignTop(ring, board)
    Below(left_gusset, ring, gap=8)
    AlignLeft(left_gusset, ring)
    RightOf(right_gusset, left_gusset, gap=8)
    AlignTop(right_gusset, left_gusset)
    Below(left_hook, board, gap=8)
    AlignLeft(left_hook, board)
    RightOf(right_hook, left_hook, gap=8)
    AlignTop(right_hook, left_hook)

    # the request's numbers
    assert board.body.bb.width == 300 mm and board.body.bb.height == 200 mm, "board 300 x 200"
    assert ring.opening.c.diameter == 150 mm, "150 mm inside"
    assert ring.outer.radius - ring.opening.c.radius == 12 mm, "ring 12 wide"
    assert (ring.neck.bb.top - T) - ring.outer.bb.top == 10 mm, "10 mm clear of the board"
    assert len(ring.net.s) == 10, "10 net notches"
    assert board.marks.target.bb.bottom - RIM_TOP == 2 mm and RIM_TOP == -30 mm, "box on the rim"
    assert board.marks.target.width == 120 mm and board.marks.target.height == 90 mm, "box"
    assert left_hook.back_leg.bb.left - left_hook.front_leg.bb.right == 40 mm + 4 mm, "door"
    assert left_hook.bar.bb.bottom - left_hook.strip.bb.top == 15 mm, "bar 15 above the board"
    assert left_hook.back_leg.bb.height == 40 mm, "back leg 40"
}
