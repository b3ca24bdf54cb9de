# REQUEST (home): a wall display for three air plants, a little honeycomb of three
# hexagonal cells, 110 mm across flats (flats at top and bottom), laid out as an arch: two
# cells side by side at the bottom, 190.5 mm apart, and one between and above them (cell
# centres at (-95.26, 0), (0, 55), (95.26, 0): honeycomb neighbours). Five parts. A 3 mm ply
# back, the three hexagons' union, hung on two screws by keyholes (8 mm head, 4 mm slot,
# 10 mm long, upwards) 25 mm above the centres of the two bottom cells. A 6 mm ply frame
# glued on the back: each cell's outline as a wall 6 mm wide inside it. In each cell a
# ledge of 6 mm ply, 50 mm wide, standing out 35 mm from the back's face, front corners R8,
# lying on the frame's bottom wall and glued into the back by two 12 mm tenons (through
# mortises). "TILLANDSIA" engraved on the back in the top cell, serif 6 mm, 22 mm above that
# cell's centre. Shown on the wall.

units mm
import "std/joints.aidl"
import "std/plates.aidl"

af = 110 mm
wall = 6 mm
t_back = 3 mm
t_ply = 6 mm
step = 1.5 * af / sqrt(3)          # honeycomb neighbours: 1.5 x the corner radius across
cells = [(-step, 0), (0, af / 2), (step, 0)]

def ledge() -> solid {
    thickness t_ply
    # drawn with its tenons' tips on y = 0 (the wall side of the back), standing out to -y
    body = RoundedRectangle(corner=(-25, -(t_back + 35)), opposite=(25, 0),
                            corner_radii=[0, 0, 8, 8])
    tenons = tab_and_slot(part="tab", length=50 mm, thickness=t_back, tabs=2, tab=12 mm,
                          screw=0, cx=0 mm, cy=0 mm)
}

assembly display {
    solid back {
        thickness t_back
        for i in range(3) {
            cell = RegularPolygon(center=cells[i], across_flats=af, sides=6)
            m = tab_and_slot(part="slot", length=50 mm, thickness=t_ply, tabs=2, tab=12 mm,
                             screw=0, cx=cells[i][0], cy=cells[i][1] - af / 2 + wall + t_ply / 2)
        }
        left_hook = keyhole(head=8 mm, slot_width=4 mm, length=10 mm, direction=90 deg,
                            cx=cells[0][0], cy=cells[0][1] + 25 mm)
        right_hook = keyhole(head=8 mm, slot_width=4 mm, length=10 mm, direction=90 deg,
                             cx=cells[2][0], cy=cells[2][1] + 25 mm)
        drawing name {
            w = Text("TILLANDSIA", position=(cells[1][0], cells[1][1] + 22), size=6,
                     font="serif")
        }
    }
    solid frame {
        thickness t_ply
        for i in range(3) {
            ring = Shell(RegularPolygon(center=cells[i], across_flats=af, sides=6), -wall)
        }
    }
    for i in range(3) {
        l = ledge()
        # world frame: the back's wall side on y = 0, its drawing's y is z
        Place(l, position=(cells[i][0], 0, cells[i][1] - af / 2 + wall),
              face="up", up="back")
    }

    # flat, for cutting
    RightOf(frame, back, gap=10)
    AlignBottom(frame, back)
    Below(l[0], back, gap=10)
    AlignLeft(l[0], back)
    RightOf(l[1], l[0], gap=10)
    AlignTop(l[1], l[0])
    RightOf(l[2], l[1], gap=10)
    AlignTop(l[2], l[1])

    # 3D: the back on the wall (y = 0), its face to the front; the frame on it
    Place(back, position=(0, 0, 0), face="front", up="up")
    Place(frame, on=back, position=(0, 0))
}

# the request's numbers
assert len(display.back.cell) == 3 and len(display.frame.ring) == 3, "three cells"
assert display.back.cell[0].across_flats == 110 mm, "cells 110 mm across flats"
assert abs(display.back.cell[2].center.x - display.back.cell[0].center.x - 190.5 mm) < 0.1 mm, "bottom cells 190.5 apart"
assert abs(distance(display.back.cell[0].center, display.back.cell[1].center) - 110 mm) < 0.01 mm, "honeycomb neighbours"
assert display.back.right_hook.head_hole.center.y - display.back.cell[2].center.y == 25 mm, "keyholes 25 mm up"
assert len(display.l) == 3, "three ledges"
assert display.l[0].body.width == 50 mm, "ledges 50 mm wide"
assert display.l[0].body.height - t_back == 35 mm, "ledges stand out 35 mm"
assert distance(display.back.name, display.frame) >= 3 mm, "the name clear of the frame"
assert distance(display.back.name, display.back.m[1].slot[0]) >= 3 mm, "the name clear of the mortises"
