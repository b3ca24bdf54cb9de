# Request: a set of pattern blocks for my niece, cut from 6 mm birch ply, every edge 25 mm
# (the trapezoid's long edge 50 mm): 4 hexagons, 6 trapezoids (half hexagons), 8 triangles,
# 6 squares, 8 "blue" rhombi (60 deg) and 8 "tan" rhombi (30 deg): 40 pieces. They live in a
# finger-jointed tray of the same ply, 180 x 120 x 45 mm outside, with 2 x 3 compartments
# (one shape each: hexagons, trapezoids and squares in the front row; triangles, blue and tan
# rhombi in the back row, the eights in two piles of four), and the outline of each
# compartment's shape engraved on the tray's bottom in that compartment, as a sorting guide.

import "std/boxes.aidl"

t = 6 mm
thickness t
side = 25 mm
h3 = side * sqrt(3) / 2

tray_l = 180 mm
tray_w = 120 mm
tray_h = 45 mm
inner_l = tray_l - 2 * t
inner_w = tray_w - 2 * t
cell_w = (inner_l - 2 * t) / 3
cell_h = (inner_w - t) / 2
def col_x(c) = -inner_l / 2 + cell_w / 2 + c * (cell_w + t)
def row_y(r) = -inner_w / 2 + cell_h / 2 + r * (cell_h + t)

def rhomb_pts(a, cx=0 mm, cy=0 mm) = [(cx - (side + side * cos(a)) / 2, cy - side * sin(a) / 2),
                    (cx + (side - side * cos(a)) / 2, cy - side * sin(a) / 2),
                    (cx + (side + side * cos(a)) / 2, cy + side * sin(a) / 2),
                    (cx - (side - side * cos(a)) / 2, cy + side * sin(a) / 2)]

def hex_block() -> solid { s = RegularPolygon(center=(0, 0), side=side, sides=6) }
def trap_block() -> solid { s = Trapezoid(center=(0, 0), bottom_width=2 * side, top_width=side, height=h3) }
def tri_block() -> solid { s = Triangle(center=(0, 0), base=side, height=h3) }
def square_block() -> solid { s = Rectangle(center=(0, 0), width=side, height=side) }
def rhomb_block(a=60 deg) -> solid { s = Polygon(rhomb_pts(a)) }

assembly kit {
    tray = divider_tray(length=tray_l, width=tray_w, height=tray_h, rows=2, cols=3,
                        thickness=t, finger=15 mm)

    # sorting guide engraved on the tray's bottom, one outline per compartment
    drawing guide {
        hex = RegularPolygon(center=(col_x(0), row_y(0)), side=side, sides=6)
        trap = Trapezoid(center=(col_x(1), row_y(0)), bottom_width=2 * side, top_width=side, height=h3)
        sq = Rectangle(center=(col_x(2), row_y(0)), width=side, height=side)
        tri = Triangle(center=(col_x(0), row_y(1)), base=side, height=h3)
        blue = Polygon(rhomb_pts(60 deg, col_x(1), row_y(1)))
        tan = Polygon(rhomb_pts(30 deg, col_x(2), row_y(1)))
    }
    guide.hex.center.x == tray.body.bottom.bb.center_x + col_x(0)
    guide.hex.center.y == tray.body.bottom.bb.center_y + row_y(0)
    CutInto(guide, tray.body.bottom)

    for i in range(4) { hx = hex_block() }
    for i in range(6) { tp = trap_block() }
    for i in range(6) { sq = square_block() }
    for i in range(8) { tr = tri_block() }
    for i in range(8) { bl = rhomb_block(a=60 deg) }
    for i in range(8) { tn = rhomb_block(a=30 deg) }

    # flat: one row per shape above the tray's panels
    Above(hx[0], tray, gap=10)
    AlignLeft(hx[0], tray)
    Above(tp[0], hx[0], gap=4)
    AlignLeft(tp[0], hx[0])
    Above(sq[0], tp[0], gap=4)
    AlignLeft(sq[0], hx[0])
    Above(tr[0], sq[0], gap=4)
    AlignLeft(tr[0], hx[0])
    Above(bl[0], tr[0], gap=4)
    AlignLeft(bl[0], hx[0])
    Above(tn[0], bl[0], gap=4)
    AlignLeft(tn[0], hx[0])
    for i in range(1, 4) {
        RightOf(hx[i], hx[i - 1], gap=4)
        AlignBottom(hx[i], hx[i - 1])
    }
    for i in range(1, 6) {
        RightOf(tp[i], tp[i - 1], gap=4)
        AlignBottom(tp[i], tp[i - 1])
    }
    for i in range(1, 6) {
        RightOf(sq[i], sq[i - 1], gap=4)
        AlignBottom(sq[i], sq[i - 1])
    }
    for i in range(1, 8) {
        RightOf(tr[i], tr[i - 1], gap=4)
        AlignBottom(tr[i], tr[i - 1])
    }
    for i in range(1, 8) {
        RightOf(bl[i], bl[i - 1], gap=4)
        AlignBottom(bl[i], bl[i - 1])
    }
    for i in range(1, 8) {
        RightOf(tn[i], tn[i - 1], gap=4)
        AlignBottom(tn[i], tn[i - 1])
    }

    # assembled: stacked in their compartments on the tray's bottom (its top face at z = t)
    for i in range(4) { Place(hx[i], position=(col_x(0), row_y(0), t + i * t), face="up") }
    for i in range(6) { Place(tp[i], position=(col_x(1), row_y(0), t + i * t), face="up") }
    for i in range(6) { Place(sq[i], position=(col_x(2), row_y(0), t + i * t), face="up") }
    for i in range(8) {
        Place(tr[i], position=(col_x(0) + (13 mm if i < 4 else -13 mm), row_y(1), t + (i % 4) * t), face="up")
        Place(bl[i], position=(col_x(1), row_y(1) + (12 mm if i < 4 else -12 mm), t + (i % 4) * t), face="up")
        Place(tn[i], position=(col_x(2), row_y(1) + (10 mm if i < 4 else -10 mm), t + (i % 4) * t), face="up")
    }

    assert len(hx) == 4 and len(tp) == 6 and len(sq) == 6, "4 hexagons, 6 trapezoids, 6 squares"
    assert len(tr) == 8 and len(bl) == 8 and len(tn) == 8, "8 triangles, 8 blue, 8 tan"
    assert len(hx) + len(tp) + len(sq) + len(tr) + len(bl) + len(tn) == 40, "40 pieces"
    assert hx[0].s.side == 25 mm, "hexagon edge 25"
    assert tp[0].s.top_width == 25 mm and tp[0].s.bottom_width == 50 mm, "trapezoid 25 / 50"
    assert distance(tp[0].s.top_left, tp[0].s.bottom_left) == 25 mm, "trapezoid legs 25"
    assert sq[0].s.width == 25 mm and sq[0].s.height == 25 mm, "square 25"
    assert distance(tr[0].s.a, tr[0].s.c) == 25 mm and tr[0].s.base == 25 mm, "triangle 25"
    assert distance(bl[0].s.points[0], bl[0].s.points[1]) == 25 mm, "blue rhombus edge 25"
    assert distance(bl[0].s.points[1], bl[0].s.points[2]) == 25 mm, "blue rhombus edge 25"
    assert distance(bl[0].s.points[0], bl[0].s.points[3]) == 25 mm, "blue rhombus short diagonal = edge at 60 deg"
    assert distance(tn[0].s.points[1], tn[0].s.points[2]) == 25 mm, "tan rhombus edge 25"
    assert tn[0].s.bb.height == 12.5 mm, "tan rhombus at 30 deg: height 25 sin 30"
    assert hx[0].s.bb.width <= cell_w and hx[0].s.bb.height <= cell_h, "a hexagon fits its cell"
    assert tp[0].s.bb.width <= cell_w, "a trapezoid fits its cell"
    assert tn[0].s.bb.width <= cell_w, "a tan rhombus fits its cell"
    assert 5 * t <= tray_h, "piles of four stay under the walls' tops"
    assert 7 * t <= tray_h, "six trapezoids stay under the walls' tops"
}
