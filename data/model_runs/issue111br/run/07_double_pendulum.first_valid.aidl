# Request: a desk double pendulum to show chaos, 6 mm plywood. A 300 mm wide upright, 450 mm
# tall above the base, top corners r20, with a 22 mm press fit for a 608 bearing 380 mm above
# the base, "DOUBLE PENDULUM" engraved 10 mm tall 40 mm above the base. It stands on a 300 x
# 200 mm base (its mid-plane 50 mm behind the base's middle) with three 20 mm glued tabs, and
# is braced by two 80 mm deep, 100 mm tall gussets in front, 140 mm either side of the middle,
# each tabbed (2 x 15 mm) into upright and base. Arm 1: 36 mm wide with round ends, 120 mm
# between an 8 mm hole for the shaft (glued) and a 22 mm bearing seat for arm 2's shaft.
# Arm 2: 24 mm wide, round ends, 100 mm between its 8 mm shaft hole and a 10 mm hole for a
# bolt as a bob. "CHAOS" engraved 8 mm tall along arm 2.

units mm
thickness 6 mm

import "std/joints.aidl"

T = 6 mm
W = 300 mm
BOARD_H = 450 mm
PIVOT_H = 380 mm
BOARD_Y = 50 mm         # the upright's mid-plane, from the base's middle toward the back
G_X = 140 mm            # the gussets' mid-planes, either side
G_D = 80 mm
G_H = 100 mm
L1 = 120 mm
L2 = 100 mm
A1 = 60 deg             # the pose shown in 3D: turns about y (0: arm pointing along +x)
A2 = 150 deg

def gusset() -> solid {
    # x out from the upright's face, y up from the base's underside
    body = Polygon([(-T, T), (-T, T + G_H), (0, T + G_H), (G_D, T + 8), (G_D, 0), (0, 0), (0, T)])
    upright_tabs = tab_and_slot(part="tab", length=G_H, thickness=T, tabs=2, tab=15 mm,
                                screw=0, rotation=90 deg, cx=-T, cy=T + G_H / 2)
    base_tabs = tab_and_slot(part="tab", length=G_D, thickness=T, tabs=2, tab=15 mm, screw=0,
                             rotation=180 deg, cx=G_D / 2, cy=0)
}

assembly pendulum {
    solid base {
        plate = RoundedRectangle(center=(0, 0), width=W, height=200, corner_radius=8)
        board_slots = tab_and_slot(part="slot", length=W, thickness=T, tabs=3, tab=20 mm,
                                   screw=0, clearance=0.1 mm, cx=0, cy=BOARD_Y)
        left_slots = tab_and_slot(part="slot", length=G_D, thickness=T, tabs=2, tab=15 mm,
                                  screw=0, clearance=0.1 mm, rotation=90 deg,
                                  cx=-G_X, cy=BOARD_Y - T / 2 - G_D / 2)
        right_slots = tab_and_slot(part="slot", length=G_D, thickness=T, tabs=2, tab=15 mm,
                                   screw=0, clearance=0.1 mm, rotation=90 deg,
                                   cx=G_X, cy=BOARD_Y - T / 2 - G_D / 2)
    }

    # the upright, y up from the base's underside (its tabs reach down through the base)
    solid upright {
        body = RoundedRectangle(bottom_left=(-W / 2, 0), width=W, height=BOARD_H + T,
                                corner_radii=[20, 20, 0, 0])
        base_tabs = tab_and_slot(part="tab", length=W, thickness=T, tabs=3, tab=20 mm, screw=0,
                                 rotation=180 deg, cx=0, cy=0)
        hole bearing { c = Circle(center=(0, T + PIVOT_H), diameter=22) }
        left_slots = tab_and_slot(part="slot", length=G_H, thickness=T, tabs=2, tab=15 mm,
                                  screw=0, clearance=0.1 mm, rotation=90 deg,
                                  cx=-G_X, cy=T + G_H / 2)
        right_slots = tab_and_slot(part="slot", length=G_H, thickness=T, tabs=2, tab=15 mm,
                                   screw=0, clearance=0.1 mm, rotation=90 deg,
                                   cx=G_X, cy=T + G_H / 2)
        drawing title {
            t = Text("DOUBLE PENDULUM", position=(0, T + 40 mm), size=10, valign="middle")
        }
    }

    left_gusset = gusset()
    right_gusset = gusset()

    solid arm1 {
        bar = Slot(start=(0, 0), end=(L1, 0), width=36)
        hole shaft { c = Circle(center=(0, 0), diameter=8) }
        hole bearing { c = Circle(center=(L1, 0), diameter=22) }
    }

    solid arm2 {
        bar = Slot(start=(0, 0), end=(L2, 0), width=24)
        hole shaft { c = Circle(center=(0, 0), diameter=8) }
        hole bob { c = Circle(center=(L2, 0), diameter=10) }
        drawing word { t = Text("CHAOS", position=(L2 / 2, 0), size=8, valign="middle") }
    }

    # 3D: x across, y from front (-) to back (+), z up from the base's underside
    Place(base, position=(0, 0, 0))
    Place(upright, rotation=(90 deg, 0, 0), position=(0, BOARD_Y + T / 2, 0))
    Place(left_gusset, rotation=(90 deg, 0, -90 deg), position=(-G_X + T / 2, BOARD_Y - T / 2, 0))
    Place(right_gusset, rotation=(90 deg, 0, -90 deg), position=(G_X + T / 2, BOARD_Y - T / 2, 0))
    # the arms in front of the upright, 3 mm apart, turned about the pivot
    Place(arm1, rotation=(90 deg, A1, 0), position=(0, BOARD_Y - T / 2 - 3 mm, T + PIVOT_H))
    Place(arm2, rotation=(90 deg, A2, 0),
          position=(L1 * cos(A1), BOARD_Y - T / 2 - 3 mm - T - 3 mm, T + PIVOT_H - L1 * sin(A1)))

    # the sheet
    RightOf(upright, base, gap=5)
    Above(arm1, base, gap=5)
    AlignLeft(arm1, base)
    Above(arm2, arm1, gap=5)
    AlignLeft(arm2, base)
    RightOf(left_gusset, upright, gap=5)
    Above(right_gusset, left_gusset, gap=5)
    AlignLeft(right_gusset, left_gusset)

    # the request's numbers
    assert upright.bearing.c.center.y - upright.base_tabs.gap[0].bb.top == 380 mm,
        "pivot 380 above the base"
    assert upright.body.bb.height - T == 450 mm and upright.body.bb.width == 300 mm,
        "upright 300 x 450 above the base"
    assert base.plate.bb.height == 200 mm, "base 200 deep"
    assert distance(arm1.shaft.c.center, arm1.bearing.c.center) == 120 mm, "arm 1: 120"
    assert distance(arm2.shaft.c.center, arm2.bob.c.center) == 100 mm, "arm 2: 100"
    assert arm1.bar.width == 36 mm and arm2.bar.width == 24 mm, "arm widths"
    # the pendulum hanging straight down clears the base, and its sweep misses the gussets
    assert PIVOT_H - L1 - L2 - 12 mm >= 100 mm, "hangs clear of the base"
    assert sqrt(square(G_X - T / 2) + square(PIVOT_H - G_H)) > L1 + L2 + 12 mm,
        "the sweep clears the gussets"
}
