# Request: a counting-frame abacus for a toddler, all in 6 mm plywood. Ten 5 mm dowel rods, 18 mm
# apart, the lowest 30 mm above the base, each carrying ten 16 mm beads (6 mm hole) cut from the
# same ply: 100 beads. The rods span 160 mm between two uprights, 60 wide and 230 tall above the
# base with a round top, each glued into the base with two 15 mm tabs; the rod holes in the
# uprights are 5 mm for a press fit. A 20 mm top rail joins the uprights just under their tops,
# its 10 mm tenons through them. The base is 200 x 80 with r6 corners and "COUNT TO 100" engraved
# 6 mm tall at its front. The left upright carries the rod numbers 1 to 10 (bottom to top)
# engraved 6 mm tall on its outer face beside each rod.

import "std/joints.aidl"

thickness 6 mm
T = 6 mm
RODS = 10
BEADS = 10
PITCH = 18 mm
FIRST = 30 mm
SPAN = 160 mm
UP_W = 60 mm
UP_H = 230 mm
RAIL_Y = 215 mm       # rail centre above the base's top
BEAD_D = 16 mm

def upright(numbers=false) -> solid {
    body = RoundedRectangle(bottom_left=(-UP_W / 2, -T), width=UP_W, height=T + UP_H,
                            corner_radii=[UP_W / 2, UP_W / 2, 0, 0])
    feet = tab_and_slot(part="tab", length=UP_W, thickness=T, tabs=2, tab=15 mm, screw=0,
                        rotation=180 deg, cx=0, cy=-T)
    mortise = tab_and_slot(part="slot", length=20 mm, thickness=T, tabs=1, tab=10 mm, screw=0,
                           rotation=90 deg, cx=0, cy=RAIL_Y)
    for i in range(RODS) {
        hole rod { c = Circle(center=(0, FIRST + i * PITCH), diameter=5) }
    }
    if numbers {
        drawing marks {
            for i in range(RODS) {
                n = Text(str(i + 1), position=(-18, FIRST + i * PITCH), size=6, valign="middle")
            }
        }
    }
    Fixed(body)
}

def bead(x=0 mm, y=0 mm) -> solid {
    ring = Circle(center=(x, y), diameter=BEAD_D)
    hole bore { c = Circle(center=(x, y), diameter=6) }
    Fixed(ring)
}

assembly abacus {
    solid base {
        board = RoundedRectangle(center=(0, 0), width=200, height=80, corner_radius=6)
        left_slots = tab_and_slot(part="slot", length=UP_W, thickness=T, tabs=2, tab=15 mm,
                                  screw=0, rotation=90 deg, cx=-SPAN / 2 - T / 2, cy=0)
        right_slots = tab_and_slot(part="slot", length=UP_W, thickness=T, tabs=2, tab=15 mm,
                                   screw=0, rotation=90 deg, cx=SPAN / 2 + T / 2, cy=0)
        drawing label {
            t = Text("COUNT TO 100", position=(0, -30), size=6, valign="middle")
        }
        Fixed(board)
        assert board.bb.width == 200 mm and board.bb.height == 80 mm, "base 200 x 80"
    }

    left = upright(numbers=true)
    right = upright()

    solid rail {
        bar = Rectangle(center=(0, 0), width=SPAN + 2 * T, height=20)
        left_tenon = tab_and_slot(part="tab", length=20 mm, thickness=T, tabs=1, tab=10 mm,
                                  screw=0, rotation=90 deg, cx=-SPAN / 2 - T, cy=0)
        right_tenon = tab_and_slot(part="tab", length=20 mm, thickness=T, tabs=1, tab=10 mm,
                                   screw=0, rotation=-90 deg, cx=SPAN / 2 + T, cy=0)
        Fixed(bar)
    }

    for r in range(RODS) {
        for c in range(BEADS) {
            b = bead(x=130 mm + c * 20 mm, y=r * 20 mm)
            # 3D: on rod r, stacked from the left upright
            Place(b, rotation=(90 deg, 0, 90 deg),
                  position=(-SPAN / 2 + c * T, -(130 mm + c * 20 mm), T + FIRST + r * PITCH - r * 20 mm))
        }
    }

    assert len(b) == 10 and len(b[0]) == 10, "100 beads"
    assert len(left.rod) == 10, "ten rods"
    assert left.rod[1].c.center.y - left.rod[0].c.center.y == 18 mm, "rods 18 apart"
    assert left.rod[0].c.center.y - (left.body.bb.bottom + T) == 30 mm, "lowest rod 30 up"
    assert left.body.bb.height - T == 230 mm, "uprights 230 tall"
    assert rail.bar.bb.width - 2 * T == 160 mm, "160 between the uprights"

    # sheet
    Below(left, base, gap=8)
    AlignLeft(left, base)
    RightOf(right, left, gap=8)
    AlignTop(right, left)
    RightOf(rail, right, gap=8)
    AlignTop(rail, right)

    # 3D: base flat, rods along x
    Place(base, position=(0, 0, 0))
    Place(right, rotation=(90 deg, 0, 90 deg), position=(SPAN / 2, 0, T))
    Place(left, rotation=(90 deg, 0, -90 deg), position=(-SPAN / 2, 0, T))
    Place(rail, rotation=(90 deg, 0, 0), position=(0, T / 2, T + RAIL_Y))
}
