# Request (pets): a play maze for a Syrian hamster, 6 mm poplar ply. An open-top box 400 x 300 mm
# outside and 120 mm tall, finger-jointed (15 mm fingers), with a 50 mm round doorway in the
# left end wall for a play tube, its centre 34 mm above the bottom (28 mm above the floor) and
# 96 mm from the box's middle toward the front. Inside, four maze walls 100 mm tall, each with
# two 15 mm tabs glued through mortises in the floor: two long walls across (234 mm, one from
# each end wall, at 48 mm either side of the middle) and two short ones along the depth
# (134 mm from the front, 110 mm left of the middle; 84 mm from the back, 120 mm right of it).
# Every passage at least 50 mm wide. "HAMMY'S MAZE" engraved on the front, 16 mm bold filled.

thickness 6 mm

import "std/joints.aidl"

L = 400 mm
D = 300 mm
H = 120 mm
T = 6 mm
WALL_H = 100 mm
IN_X = L / 2 - T      # inner faces of the end walls: x = +-194
IN_Y = D / 2 - T      # inner faces of the front and back: y = +-144

# maze walls: [centre x, centre y, length, along x?]
WALLS = [[-77, 48, 234, true], [77, -48, 234, true], [-110, -77, 134, false], [120, 102, 84, false]]

def maze_wall(length=100 mm) -> solid {
    body = Rectangle(center=(0, 0), width=length, height=WALL_H)
    # two tabs on the bottom edge (y = -WALL_H / 2), the wall above it
    feet = tab_and_slot(part="tab", length=length, thickness=T, tabs=2, tab=15 mm, screw=0,
                        rotation=180 deg, cx=0 mm, cy=-WALL_H / 2)
}

assembly maze {
    box = finger_box(length=L, depth=D, height=H, thickness=T, finger=15 mm, closed=false)

    for i in range(len(WALLS)) {
        w = WALLS[i]
        wall = maze_wall(length=w[2])
        hole mortise = tab_and_slot(part="slot", length=w[2], thickness=T, tabs=2, tab=15 mm,
                                    screw=0, rotation=0 deg if w[3] else 90 deg,
                                    cx=w[0], cy=w[1])
        CutInto(mortise, box.bottom)
        # on the sheet: in a column right of the box's net
        wall.bb.left == 340 mm
        wall.bb.top == 275 mm - i * 110 mm
        # assembled: standing on the floor, tabs through it
        if w[3] {
            Place(wall, position=(w[0], w[1] + T / 2, WALL_H / 2), rotation=(90 deg, 0, 0))
        } else {
            Place(wall, position=(w[0] - T / 2, w[1], WALL_H / 2), rotation=(90 deg, 0, 90 deg))
        }
    }

    hole door { c = Circle(center=(0, 0), diameter=50) }
    door.c.center.x == box.left.bb.right - 34 mm
    door.c.center.y == box.bottom.outline.center.y - 96 mm
    CutInto(door, box.left)

    drawing name {
        t = Text("HAMMY'S MAZE", position=(0, 0), size=16, font="sans:Bold", valign="middle",
                 fill=true)
    }
    CenterInside(name, box.front.outline)
    CutInto(name, box.front)

    # the request's numbers
    assert len(wall) == 4, "four maze walls"
    assert wall[0].body.height == 100 mm, "walls 100 tall"
    assert box.front.outline.width == 400 mm and box.left.outline.height == 300 mm, "400 x 300"
    assert door.c.diameter == 50 mm, "50 mm doorway"
    # passages at least 50 mm: each wall's free end to the nearest wall across
    assert IN_X - (WALLS[0][0] + WALLS[0][2] / 2) >= 50 mm, "passage past wall 1"
    assert (WALLS[1][0] - WALLS[1][2] / 2) + IN_X >= 50 mm, "passage past wall 2"
    assert (WALLS[0][1] - T / 2) - (WALLS[2][1] + WALLS[2][2] / 2) >= 50 mm, "passage past wall 3"
    assert (WALLS[3][1] - WALLS[3][2] / 2) - (WALLS[1][1] + T / 2) >= 50 mm, "passage past wall 4"
    # walls that meet an outer wall end at its inner face
    assert WALLS[0][0] - WALLS[0][2] / 2 == -IN_X, "wall 1 from the left end"
    assert WALLS[2][1] - WALLS[2][2] / 2 == -IN_Y, "wall 3 from the front"
    assert WALLS[3][1] + WALLS[3][2] / 2 == IN_Y, "wall 4 from the back"
}
