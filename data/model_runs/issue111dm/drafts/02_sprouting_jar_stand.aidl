# Request (kitchen): a draining stand for three 1-litre wide-mouth sprouting jars, 6 mm
# birch ply. The jars hang mouth-down at 45 degrees through three 92 mm holes (the 87 mm
# lid band drops through, the shoulder rests on the board) at 115 mm pitch in a rack board
# 350 mm between the sides and 160 mm along its slope, rising toward the back. Two side
# panels, 220 mm deep and 230 mm tall, hold the rack by two 30 mm tabs in each end and a
# base board (350 between the sides, 200 deep, 20 mm up to its middle) that catches the
# drips, also by two 30 mm tabs each end; the rack's middle line is 120 mm up. The sides
# have a 45 degree top edge 21 mm above the rack's middle plane, rounded R12 corners at the
# top, and "SPROUTS" engraved filled on their outsides along the slope. Under each hole the
# rack is engraved with what grows there: MUNG, ALFALFA, LENTILS.

import "std/joints.aidl"

thickness 6 mm
t = 6 mm

param inner = 350 mm, min = 300 mm, max = 400 mm   # between the sides
param pitch = 115 mm, min = 105 mm, max = 125 mm
hole_d = 92 mm
rack_len = 160 mm
rack_y = 120 mm          # the rack's middle line, up from the floor (side frame: y)
base_y = 20 mm
base_depth = 200 mm
tab_w = 30 mm
seeds = ["MUNG", "ALFALFA", "LENTILS"]

# s = 1: the front is at -x (seen from the right); s = -1: its mirror, for the left side
def side_panel(s=1) -> solid {
    p = Polygon([(-110 * s, 0), (110 * s, 0), (110 * s, 230), (80 * s, 230), (-110 * s, 40)])
    Fillet([p.points[2], p.points[3], p.points[4]], 12 mm)
    rack_m = tab_and_slot(part="slot", length=rack_len, thickness=t, tabs=2, tab=tab_w,
                          screw=0, rotation=45 deg * s, cx=0 mm, cy=rack_y)
    base_m = tab_and_slot(part="slot", length=base_depth, thickness=t, tabs=2, tab=tab_w,
                          screw=0, rotation=0 deg, cx=0 mm, cy=base_y)
    drawing word {
        w = Text("SPROUTS", position=(27.6 * s, 92.4), size=14, font="sans:Bold",
                 valign="middle", rotation=45 deg * s, fill=true)
    }
}

assembly sprout_stand {
    right = side_panel(s=1)
    left = side_panel(s=-1)

    solid rack {
        board = Rectangle(center=(0, 0), width=inner + 2 * t, height=rack_len)
        left_t = tab_and_slot(part="tab", length=rack_len, thickness=t, tabs=2, tab=tab_w,
                              screw=0, rotation=90 deg, cx=-inner / 2 - t, cy=0 mm)
        right_t = tab_and_slot(part="tab", length=rack_len, thickness=t, tabs=2, tab=tab_w,
                               screw=0, rotation=-90 deg, cx=inner / 2 + t, cy=0 mm)
        hole jars {
            for i in range(3) {
                c = Circle(center=((i - 1) * pitch, 10), diameter=hole_d)
            }
        }
        drawing labels {
            for i in range(3) {
                l = Text(seeds[i], position=((i - 1) * pitch, -58), size=8, valign="middle")
            }
        }
    }

    solid base {
        board = Rectangle(center=(0, 0), width=inner + 2 * t, height=base_depth)
        left_t = tab_and_slot(part="tab", length=base_depth, thickness=t, tabs=2, tab=tab_w,
                              screw=0, rotation=90 deg, cx=-inner / 2 - t, cy=0 mm)
        right_t = tab_and_slot(part="tab", length=base_depth, thickness=t, tabs=2, tab=tab_w,
                               screw=0, rotation=-90 deg, cx=inner / 2 + t, cy=0 mm)
    }

    # flat on the sheet
    RightOf(left, right, gap=10)
    AlignBottom(left, right)
    Above(rack, right, gap=10)
    AlignLeft(rack, right)
    Above(base, rack, gap=10)
    AlignLeft(base, rack)

    # in 3D: sides stand at x = +-inner/2, their outsides out; the rack on its 45 degree
    # line through (y 0, z 120), its top face up and to the front; the base 20 mm up
    Place(right, position=(inner / 2, 0, 0), face="right", up="up")
    Place(left, position=(-inner / 2, 0, 0), face="left", up="up")
    Place(rack, position=(0, t / 2 * sqrt(2) / 2, rack_y - t / 2 * sqrt(2) / 2),
          face=(0, -1, 1), up=(0, 1, 1))
    Place(base, position=(0, 0, base_y - t / 2), face="up", up="back")

    # the request's numbers
    assert len(rack.jars.c) == 3
    assert rack.jars.c[0].diameter == 92 mm
    assert rack.jars.c[1].center.x - rack.jars.c[0].center.x == 115 mm
    assert rack.board.width - 2 * t == 350 mm and rack.board.height == 160 mm
    assert right.p.bb.width == 220 mm and right.p.bb.height == 230 mm
    assert base.board.height == 200 mm
}
