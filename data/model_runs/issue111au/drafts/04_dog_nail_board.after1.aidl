# Request: a dog nail scratch board (the dog files its own nails on sandpaper),
# 6 mm plywood, three parts. The board is 300 x 150 mm and carries a sheet of
# sandpaper; it slopes at 30 degrees, lying on two identical triangular cheeks
# whose sloping edge is 280 mm long (the board overhangs 10 mm at each end).
# Each cheek has two glued tabs 30 mm wide along its sloping edge, in slots in
# the board 15 mm in from its long edges. A paw print is engraved on the
# outside of each cheek.

import "std/joints.aidl"

units mm
thickness 6 mm

param ply = 6 mm, min = 3 mm, max = 9 mm
param slope = 30 deg, min = 20 deg, max = 40 deg
param edge = 280 mm, min = 200 mm, max = 320 mm
param board_l = 300 mm, min = 220 mm, max = 340 mm
param board_w = 150 mm, min = 100 mm, max = 200 mm
param inset = 15 mm, min = 8 mm, max = 30 mm
param tab = 30 mm, min = 15 mm, max = 50 mm

run = edge * cos(slope)
rise = edge * sin(slope)

def cheek() -> solid {
    tri = Polygon([(0, 0), (run, 0), (run, rise)])
    # tabs' tips on the sloping edge, the cheek below it
    tabs = tab_and_slot(part="tab", length=edge, thickness=ply, tabs=2, tab=tab, screw=0,
                        rotation=slope, cx=run / 2, cy=rise / 2)
    drawing paw {
        pad = Ellipse(center=(0.7 * run, 0.25 * rise), rx=10, ry=8)
        # FIX after the first valid program: the two middle toes overlapped
        t1 = Circle(center=(0.7 * run - 14, 0.25 * rise + 13), radius=4)
        t2 = Circle(center=(0.7 * run - 5, 0.25 * rise + 19), radius=4)
        t3 = Circle(center=(0.7 * run + 5, 0.25 * rise + 19), radius=4)
        t4 = Circle(center=(0.7 * run + 14, 0.25 * rise + 13), radius=4)
    }
}

assembly scratch_board {
    solid board {
        plate = Rectangle(center=(0, 0), width=board_l, height=board_w)
        # the cheeks stand under the board along its length, 15 mm in from the
        # long edges to their outer faces
        near = tab_and_slot(part="slot", length=edge, thickness=ply, tabs=2, tab=tab, screw=0,
                            cx=0 mm, cy=-board_w / 2 + inset + ply / 2)
        far = tab_and_slot(part="slot", length=edge, thickness=ply, tabs=2, tab=tab, screw=0,
                           cx=0 mm, cy=board_w / 2 - inset - ply / 2)
    }
    left = cheek()
    right = cheek()
    # FIX after the first valid program: two identical cheeks put one paw on the
    # inside face; the right cheek is cut mirrored so its paw faces out too
    flip_axis = Line((0, -10), (0, 10), construction=true)
    Flip(right, about=flip_axis)
    Below(left, board, gap=10)
    AlignLeft(left, board)
    RightOf(right, left, gap=10)
    AlignBottom(right, left)

    assert board.plate.width == 300 mm and board.plate.height == 150 mm, "board 300 x 150"
    # attempt 1: the assert read absolute coordinates of a part that Below() had moved
    assert abs(atan((left.tri.points[2].y - left.tri.points[1].y) /
                    (left.tri.points[1].x - left.tri.points[0].x)) - 30 deg) < 0.01 deg, "30 degree slope"
    assert abs(distance(left.tri.points[0], left.tri.points[2]) - 280 mm) < 0.01 mm, "sloping edge 280"
    assert (board_l - edge) / 2 == 10 mm, "board overhangs 10 mm at each end"
    assert left.tabs.tab == 30 mm and left.tabs.tabs == 2, "two 30 mm tabs"
}
