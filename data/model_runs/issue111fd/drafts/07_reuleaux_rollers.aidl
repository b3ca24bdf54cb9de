# Request (science): a classroom demonstration of shapes of constant width, in 6 mm ply. A base
# 320 x 152 mm carries two side walls 320 long and 80 mm high above it, glued in by three 40 mm
# tenons each, 120 mm apart inside. Between them three rollers roll on the base: two made of
# Reuleaux triangles and one of Reuleaux pentagons, all 60 mm wide; each roller is two discs
# joined by a 6 mm dowel through a 6.2 mm hole at the disc's centre, the discs 1 mm in from the
# walls. A top board 200 x 116 mm (1 mm clearance each side) rides on the rollers and stays
# level, engraved "CONSTANT WIDTH" (filled, 12 mm) and "every roller is 60 mm wide" (strokes,
# 6 mm). Each disc is engraved "60" above its hole. The walls carry a scale along their top
# edge: a tick every 10 mm (8 mm long, 14 mm every 50 mm) numbered 0 ... 300 every 50 mm.

import "std/joints.aidl"

thickness 6 mm

T = 6 mm
WIDTH = 60 mm
BASE_L = 320 mm
BASE_W = 152 mm
WALL_H = 80 mm
INSIDE = 120 mm
BOARD_L = 200 mm
BOARD_W = 116 mm

# a Reuleaux n-gon's corners lie on a circle this big: the width spans (n - 1) / 2 sides
def corner_r(n) = WIDTH / (2 * sin(180 deg * ((n - 1) / 2) / n))

def disc(sides=3) -> solid {
    body = Intersect([Circle(center=(corner_r(sides) * cos(90 deg + i * 360 deg / sides),
                                     corner_r(sides) * sin(90 deg + i * 360 deg / sides)),
                             radius=WIDTH) for i in range(sides)])
    hole axle {
        c = Circle(center=(0, 0), diameter=6.2)
    }
    drawing mark {
        t = Text("60", position=(0, 12), size=8, valign="middle")
    }
}

def base_part() -> solid {
    body = Rectangle(center=(0, 0), width=BASE_L, height=BASE_W)
    for s in [-1, 1] {
        wall_slots = tab_and_slot(part="slot", length=BASE_L, thickness=T, tabs=3, tab=40 mm,
                                  screw=0, cx=0, cy=s * (INSIDE + T) / 2)
    }
}

def wall_part() -> solid {
    body = Rectangle(center=(0, 0), width=BASE_L, height=WALL_H + T)
    tenons = tab_and_slot(part="tab", length=BASE_L, thickness=T, tabs=3, tab=40 mm, screw=0,
                          rotation=180 deg, cx=0, cy=-(WALL_H + T) / 2)
    drawing scale {
        for k in range(31) {
            tick = Line((-150 + k * 10, (WALL_H + T) / 2),
                        (-150 + k * 10, (WALL_H + T) / 2 - (14 if k % 5 == 0 else 8)))
        }
        for k in range(7) {
            num = Text(str(k * 50), position=(-150 + k * 50, (WALL_H + T) / 2 - 22), size=5)
        }
    }
}

def board_part() -> solid {
    body = RoundedRectangle(center=(0, 0), width=BOARD_L, height=BOARD_W, corner_radius=4)
    drawing words {
        title = Text("CONSTANT WIDTH", position=(0, 8), size=12, font="sans:Bold", fill=true)
        line2 = Text("every roller is 60 mm wide", position=(0, -20), size=6)
    }
}

assembly constant_width {
    base = base_part()
    Place(base, position=(0, 0, 0), face="up", up="back")
    for s in range(2) {
        wall = wall_part()
    }
    # the walls' scales face outward; tenon tips flush with the base's underside
    Place(wall[0], position=(0, -INSIDE / 2, (WALL_H + T) / 2), face="front", up="up")
    Place(wall[1], position=(0, INSIDE / 2, (WALL_H + T) / 2), face="back", up="up")
    # rollers: disc pairs standing on the base, corner up, 1 mm in from the walls
    kinds = [3, 3, 5]
    for r in range(3) {
        near = disc(sides=kinds[r])
        far = disc(sides=kinds[r])
        Place(near, position=(-70 mm + r * 70 mm, -INSIDE / 2 + 1 mm + T, T + WIDTH - corner_r(kinds[r])),
              face="front", up="up")
        Place(far, position=(-70 mm + r * 70 mm, INSIDE / 2 - 1 mm, T + WIDTH - corner_r(kinds[r])),
              face="front", up="up")
    }
    board = board_part()
    Place(board, position=(0, 0, T + WIDTH), face="up", up="back")

    # flat on the sheet
    Below(wall[0], base, gap=8)
    AlignLeft(wall[0], base)
    Below(wall[1], wall[0], gap=8)
    AlignLeft(wall[1], wall[0])
    RightOf(board, base, gap=8)
    AlignTop(board, base)
    Below(near[0], board, gap=8)
    AlignLeft(near[0], board)
    RightOf(far[0], near[0], gap=6)
    AlignTop(far[0], near[0])
    RightOf(near[1], far[0], gap=6)
    AlignTop(near[1], far[0])
    Below(far[1], near[0], gap=6)
    AlignLeft(far[1], near[0])
    RightOf(near[2], far[1], gap=6)
    AlignTop(near[2], far[1])
    RightOf(far[2], near[2], gap=6)
    AlignTop(far[2], near[2])

    assert near[0].body.bb.width == 60 mm and near[0].body.bb.height == 60 mm, "triangle 60 wide"
    assert near[2].body.bb.width == 60 mm and near[2].body.bb.height == 60 mm, "pentagon 60 wide"
    assert near[0].axle.c.diameter == 6.2 mm, "dowel hole"
    assert base.body.bb.width == 320 mm and base.body.bb.height == 152 mm, "base 320 x 152"
    assert base.wall_slots[1].slot[0].bb.center_y - base.wall_slots[0].slot[0].bb.center_y - 6 mm == 120 mm,
        "walls 120 apart inside"
    assert wall[0].body.bb.height - 6 mm == 80 mm, "walls 80 above the base"
    assert board.body.bb.width == 200 mm and board.body.bb.height == 116 mm, "board 200 x 116"
    assert len(wall[0].scale.tick) == 31 and len(wall[0].scale.num) == 7, "scale 0 ... 300"
    assert wall[0].scale.tick[30].start.x - wall[0].scale.tick[0].start.x == 300 mm, "300 mm scale"
    assert distance(board.words.title, board.words.line2) >= 3 mm, "lines apart"
}
