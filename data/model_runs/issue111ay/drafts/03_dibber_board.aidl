# Request (garden): a dibber board for my 24-cell seed trays (4 rows x 6 cells, 38 mm cell
# pitch), from 6 mm birch ply. The board is 240 x 160 mm with 8 mm rounded corners and 24
# holes 8 mm across for 8 mm hardwood dowel pegs (glued in from below), 4 rows x 6 columns at
# 38 mm pitch, centred on the board. On top stand two handles running across the board's
# short way, 76 mm apart centre to centre (between the peg columns), each 100 mm long and
# 55 mm tall with 15 mm rounded top corners and a hand hole 70 x 22 mm (round ends) whose
# centre is 32 mm above the board's top face... each handle glued into the board with two
# 20 mm tabs. "24 CELL" engraved 8 mm tall on the board's top, 12 mm in from the front edge.

units mm
thickness 6 mm

import "std/joints.aidl"

param pitch = 38 mm, min = 30 mm, max = 50 mm
param rows = 4, min = 2, max = 6
param cols = 6, min = 3, max = 8

t = 6 mm
handle_x = 38 mm          # each handle's middle from the board's centre
handle_len = 100 mm
handle_h = 55 mm

def handle() -> solid {
    body = RoundedRectangle(bottom_left=(-handle_len / 2, 0), width=handle_len,
                            height=handle_h, corner_radii=[15, 15, 0, 0])
    hole grip {
        s = Slot(center=(0, t + 32), length=70, width=22)
    }
    tabs = tab_and_slot(part="tab", length=handle_len, thickness=t, tabs=2, tab=20 mm,
                        screw=0, rotation=180 deg, cx=0 mm, cy=0 mm)
    Fixed(body)
    Fixed(grip)
}

assembly dibber {
    solid board {
        body = RoundedRectangle(center=(0, 0), width=240, height=160, corner_radius=8)
        hole peg {
            c = Circle(center=(-(cols - 1) * pitch / 2, -(rows - 1) * pitch / 2), diameter=8)
        }
        pegs = GridPattern(peg, rows, cols, (pitch, pitch))
        left_slots = tab_and_slot(part="slot", length=handle_len, thickness=t, tabs=2,
                                  tab=20 mm, screw=0, rotation=90 deg, cx=-handle_x, cy=0 mm)
        right_slots = tab_and_slot(part="slot", length=handle_len, thickness=t, tabs=2,
                                   tab=20 mm, screw=0, rotation=90 deg, cx=handle_x, cy=0 mm)
        drawing label {
            # FIX after the first valid program: 12 mm in, the 8 mm letters ran into the
            # front row of peg holes (W0505, real); set 4 mm in from the front edge instead
            w = Text("24 CELL", position=(0, -80 + 4), size=8, valign="bottom")
        }
        Fixed(body)
        Fixed(peg)
        assert len(pegs) == 24
        assert pegs[1].c.center.x - pegs[0].c.center.x == 38 mm, "column pitch"
        assert pegs[6].c.center.y - pegs[0].c.center.y == 38 mm, "row pitch"
        assert abs(pegs[0].c.center.x + pegs[23].c.center.x) < 0.001 mm and
            abs(pegs[0].c.center.y + pegs[23].c.center.y) < 0.001 mm, "grid centred"
        assert body.bb.width == 240 mm and body.bb.height == 160 mm
        assert right_slots.bb.center_x - left_slots.bb.center_x == 76 mm, "handles 76 apart"
        assert label.bb.bottom - body.bb.bottom >= 4 mm - 0.5 mm
        assert pegs[2].c.bottom.y - label.bb.top >= 2 mm, "label clear of the pegs"
    }

    near = handle()
    far = handle()

    # flat for cutting: the handles beside the board
    RightOf(near, board, gap=6)
    RightOf(far, near, gap=6)
    AlignTop(near, board)
    AlignTop(far, board)

    # assembled: handles standing across the board, tabs through its slots
    Place(near, position=(-handle_x - t / 2, 0, 0), rotation=(90 deg, 0, 90 deg))
    Place(far, position=(handle_x - t / 2, 0, 0), rotation=(90 deg, 0, 90 deg))

    assert near.grip.s.length == 70 mm and near.grip.s.width == 22 mm
    assert near.body.bb.height == 55 mm and near.body.bb.width == 100 mm
}
