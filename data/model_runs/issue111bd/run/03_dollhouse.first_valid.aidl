# Request (toys): an open-front two-storey dollhouse from 3 mm poplar ply, glued with
# tabs in mortises. Outside 300 mm wide, 180 mm deep, 300 mm to the eaves, 400 mm to the
# ridge. Two gable side walls (180 wide, pentagon) carry the two floors (300 x 177, each
# with two 30 mm tabs per side) at 20 mm and 170 mm up (floor middles) and the back wall
# (300 x 300, three 40 mm tabs per side) at their back edge. The back wall has four
# 60 x 60 mm windows with a cross bar (four 27 mm panes, 6 mm bars), centred 70 mm either
# side of the middle at 90 and 240 mm up. The left wall has an arched door 50 mm wide, 105 mm
# tall to the top of its arch, starting 30 mm up, 20 mm in front of the wall's middle; the
# right wall a 50 mm round window at 240 mm up; both gables a 30 mm round window at 345 mm.
# The upper floor has a 50 x 100 mm stair opening at the back right, 17 mm from the right
# side wall. Two roof panels 320 mm long rest on the gables with a 10 mm overhang at the
# eaves and meet at the ridge.

import "std/joints.aidl"

thickness 3 mm

t = 3 mm
W = 300 mm           # outside width
D = 180 mm           # outside depth
eaves = 300 mm
ridge = 400 mm
floor_d = D - t      # floors stop at the back wall
floor_ys = [20 mm, 170 mm]
slope_len = sqrt((D / 2) ** 2 + (ridge - eaves) ** 2)
pitch = atan2(ridge - eaves, D / 2)
overhang = 10 mm
roof_h = overhang + slope_len

def side_wall(door=false, window=false) -> solid {
    body = Polygon([(-D / 2, 0), (D / 2, 0), (D / 2, eaves), (0, ridge), (-D / 2, eaves)])
    for k in range(len(floor_ys)) {
        floor_slots = tab_and_slot(part="slot", length=floor_d, thickness=t, tabs=2, tab=30 mm,
                                   screw=0, cx=-D / 2 + floor_d / 2, cy=floor_ys[k])
    }
    back_slots = tab_and_slot(part="slot", length=eaves, thickness=t, tabs=3, tab=40 mm,
                              screw=0, rotation=90 deg, cx=D / 2 - t / 2, cy=eaves / 2)
    hole gable { c = Circle(center=(0, 345), diameter=30) }
    if door {
        hole entrance {
            leaf = Rectangle(bottom_left=(-45, 30), width=50, height=80)
            arch = Circle(center=(-20, 110), radius=25)
        }
    }
    if window {
        hole porthole { c = Circle(center=(0, 240), diameter=50) }
    }
}

def window() -> hole {
    pane = Rectangle(center=(-16.5, -16.5), width=27, height=27)
    panes = GridPattern(pane, 2, 2, 33)
}

def floor_panel(stairs=false) -> solid {
    body = Rectangle(center=(0, 0), width=W, height=floor_d)
    left_tabs = tab_and_slot(part="tab", length=floor_d, thickness=t, tabs=2, tab=30 mm, screw=0,
                             rotation=90 deg, cx=-W / 2, cy=0 mm)
    right_tabs = tab_and_slot(part="tab", length=floor_d, thickness=t, tabs=2, tab=30 mm, screw=0,
                              rotation=-90 deg, cx=W / 2, cy=0 mm)
    if stairs {
        hole stairwell { r = Rectangle(center=(W / 2 - t - 17 mm - 25 mm, 30), width=50, height=100) }
    }
}

def roof_panel() -> solid {
    body = Rectangle(bottom_left=(-160, 0), width=320, height=roof_h)
}

assembly dollhouse {
    left_wall = side_wall(door=true)
    right_wall = side_wall(window=true)
    solid back_wall {
        body = Rectangle(bottom_left=(-W / 2, 0), width=W, height=eaves)
        left_tabs = tab_and_slot(part="tab", length=eaves, thickness=t, tabs=3, tab=40 mm, screw=0,
                                 rotation=90 deg, cx=-W / 2, cy=eaves / 2)
        right_tabs = tab_and_slot(part="tab", length=eaves, thickness=t, tabs=3, tab=40 mm, screw=0,
                                  rotation=-90 deg, cx=W / 2, cy=eaves / 2)
        for i in range(2) {
            for j in range(2) {
                win = window()
                win.bb.center == (-70 mm + 140 mm * j, 90 mm + 150 mm * i)
            }
        }
    }
    ground = floor_panel()
    upper = floor_panel(stairs=true)
    roof_front = roof_panel()
    roof_back = roof_panel()

    # on the sheet
    Fixed(left_wall)
    RightOf(right_wall, left_wall, gap=10)
    AlignBottom(right_wall, left_wall)
    RightOf(back_wall, right_wall, gap=10)
    AlignBottom(back_wall, right_wall)
    RightOf(ground, back_wall, gap=10)
    AlignBottom(ground, back_wall)
    Above(upper, ground, gap=10)
    AlignLeft(upper, ground)
    Above(roof_front, back_wall, gap=10)
    AlignLeft(roof_front, back_wall)
    Above(roof_back, upper, gap=10)
    AlignLeft(roof_back, upper)

    # assembled: x across, y front (-) to back (+), z up
    Place(left_wall, rotation=(90 deg, 0, 90 deg), position=(-W / 2, 0, 0))
    Place(right_wall, rotation=(90 deg, 0, 90 deg), position=(W / 2 - t, 0, 0))
    Place(back_wall, rotation=(90 deg, 0, 0), position=(0, D / 2, 0))
    Place(ground, position=(0, -D / 2 + floor_d / 2, floor_ys[0] - t / 2))
    Place(upper, position=(0, -D / 2 + floor_d / 2, floor_ys[1] - t / 2))
    Place(roof_front, rotation=(pitch, 0, 0),
          position=(0, -D / 2 - overhang * cos(pitch), eaves - overhang * sin(pitch)))
    Place(roof_back, rotation=(pitch, 0, 180 deg),
          position=(0, D / 2 + overhang * cos(pitch), eaves - overhang * sin(pitch)))

    # the request's numbers
    assert left_wall.body.bb.width == 180 mm and left_wall.body.bb.height == 400 mm, "side wall 180 deep, 400 to the ridge"
    assert back_wall.body.width == 300 mm and back_wall.body.height == 300 mm, "back wall 300 x 300"
    assert ground.body.width == 300 mm and ground.body.height == 177 mm, "floors 300 x 177"
    assert len(back_wall.win) == 2 and len(back_wall.win[0]) == 2, "four windows"
    assert left_wall.entrance.bb.height == 105 mm and left_wall.entrance.bb.width == 50 mm, "door 50 x 105"
    assert left_wall.entrance.bb.bottom - left_wall.body.bb.bottom == 30 mm, "door starts 30 up"
    assert right_wall.porthole.c.diameter == 50 mm, "round window 50"
    assert right_wall.porthole.c.center.y - right_wall.body.bb.bottom == 240 mm, "round window 240 up"
    assert upper.body.bb.right - t - upper.stairwell.r.bb.right == 17 mm, "stairs 17 mm from the right wall"
    assert roof_front.body.width == 320 mm, "roof 320 long"
    assert abs(roof_h - overhang - slope_len) < 0.01 mm, "roof reaches the ridge"
}
