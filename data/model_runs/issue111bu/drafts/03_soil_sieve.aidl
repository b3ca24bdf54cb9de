# Request (garden): a potting-compost sieve (a garden riddle), all 6 mm exterior ply.
# A square box 300 x 300 mm outside and 80 mm tall, its four walls finger-jointed at the corners
# (fingers about 15 mm). The mesh floor is a separate plate held 15 mm above the walls' bottom
# edge by three 20 mm tabs on each edge, going through mortises in the walls. The floor is
# pierced with 8 mm holes on an 11 mm honeycomb pitch (3 mm webs), kept at least 10 mm in from
# the walls. The two side walls have a 100 x 30 mm hand hole centred 55 mm above the bottom
# edge. "8 mm" engraved on the front wall, 12 mm tall, bold filled letters.

thickness 6 mm

import "std/joints.aidl"

SIZE = 300 mm
HEIGHT = 80 mm
T = 6 mm
FLOOR_Z = 15 mm       # the floor's underside above the walls' bottom edge
HOLE_D = 8 mm
PITCH = 11 mm
COLS = 24
ROWS = 28
ROW_STEP = PITCH * sqrt(3) / 2

def wall(ends="fingers", grip=false, label="") -> solid {
    panel = finger_panel(width=SIZE, height=HEIGHT, thickness=T, finger=15 mm,
                         bottom="flat", top="flat", left=ends, right=ends)
    # mortises for the floor's tabs, their middle T/2 above the floor's underside
    mortise = tab_and_slot(part="slot", length=SIZE, thickness=T, tabs=3, tab=20 mm, screw=0,
                           rotation=0 deg, cx=0 mm, cy=-HEIGHT / 2 + FLOOR_Z + T / 2)
    if grip {
        hole hand { s = Slot(center=(0, -HEIGHT / 2 + 55), length=100, width=30) }
    }
    if label != "" {
        drawing mark {
            t = Text(label, position=(0, 8), size=12, font="sans:Bold", valign="middle",
                     fill=true)
        }
    }
}

assembly riddle {
    front = wall(ends="fingers", label="8 mm")
    back = wall(ends="fingers")
    left = wall(ends="slots", grip=true)
    right = wall(ends="slots", grip=true)

    solid floor {
        plate = Rectangle(center=(0, 0), width=SIZE, height=SIZE)
        # three tabs on each edge, their tips at the walls' outer faces
        tabs_top = tab_and_slot(part="tab", length=SIZE, thickness=T, tabs=3, tab=20 mm,
                                screw=0, rotation=0 deg, cx=0 mm, cy=SIZE / 2)
        tabs_bottom = tab_and_slot(part="tab", length=SIZE, thickness=T, tabs=3, tab=20 mm,
                                   screw=0, rotation=180 deg, cx=0 mm, cy=-SIZE / 2)
        tabs_left = tab_and_slot(part="tab", length=SIZE, thickness=T, tabs=3, tab=20 mm,
                                 screw=0, rotation=90 deg, cx=-SIZE / 2, cy=0 mm)
        tabs_right = tab_and_slot(part="tab", length=SIZE, thickness=T, tabs=3, tab=20 mm,
                                  screw=0, rotation=270 deg, cx=SIZE / 2, cy=0 mm)
        hole mesh {
            c = Circle(center=(-((COLS - 1) * PITCH + PITCH / 2) / 2,
                               -((ROWS - 1) * ROW_STEP) / 2), diameter=HOLE_D)
        }
        holes = GridPattern(mesh, ROWS, COLS, (PITCH, ROW_STEP), stagger=true)
    }

    # flat on the sheet: walls in a column, the floor beside them
    Below(back, front, gap=6)
    Below(left, back, gap=6)
    Below(right, left, gap=6)
    AlignLeft(back, front)
    AlignLeft(left, front)
    AlignLeft(right, front)
    RightOf(floor, front, gap=10)
    AlignTop(floor, front)

    # assembled: walls standing on z = 0 round the floor
    Place(front, position=(0, -SIZE / 2 + T, HEIGHT / 2), rotation=(90 deg, 0, 0))
    Place(back, position=(0, SIZE / 2, HEIGHT / 2), rotation=(90 deg, 0, 0))
    Place(left, position=(-SIZE / 2, 0, HEIGHT / 2), rotation=(90 deg, 0, 90 deg))
    Place(right, position=(SIZE / 2 - T, 0, HEIGHT / 2), rotation=(90 deg, 0, 90 deg))
    Place(floor, position=(0, 0, FLOOR_Z))

    assert front.panel.outline.width == 300 mm and front.panel.outline.height == 80 mm, "300 x 80 walls"
    assert floor.plate.width == 300 mm, "floor reaches the outer faces"
    assert len(floor.holes) == ROWS * COLS, "every hole drawn"
    assert floor.mesh.c.diameter == 8 mm, "8 mm holes"
    assert floor.holes[1].c.center.x - floor.holes[0].c.center.x == 11 mm, "11 mm pitch"
    # 10 mm clear of the walls' inner faces (T in from the plate's edge)
    assert floor.holes[0].c.center.x - HOLE_D / 2 - (floor.plate.bb.left + T) >= 10 mm, "holes 10 mm in"
    assert floor.plate.bb.top - T - (floor.holes[ROWS * COLS - 1].c.center.y + HOLE_D / 2) >= 10 mm, "holes 10 mm in at the top"
    assert left.hand.s.center.y - left.panel.outline.bottom.midpoint.y == 55 mm, "hand hole 55 up"
    assert front.mortise.slot[0].bb.bottom - front.panel.outline.bottom.midpoint.y == 15 mm, "floor 15 mm up"
}
