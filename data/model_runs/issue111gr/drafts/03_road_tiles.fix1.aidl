# Request: jigsaw road tiles for my kids' toy cars, 6 mm ply. Each tile is 150 x 150 mm
# (R3 corners). Every edge has one knob and one socket so any edge meets any other: seen
# from outside the tile, the knob is 50 mm to the left of the edge's centre, the socket
# 50 mm to the right. The knob: an 8 mm neck and a 14 mm ball whose centre is 10 mm out
# from the edge; the socket the same shape 0.2 mm looser all round (8.4 neck, 14.4 ball).
# A road 60 mm wide runs through the middle of each edge it reaches: its edges engraved,
# a dashed centre line (10 mm dashes, 8 dashes per 150 mm: 18.75 mm pitch, so the dashes
# run on from tile to tile). Four kinds: straight (with a zebra crossing of six 4 mm
# stripes, 7 mm apart, across the middle), curve (a quarter turn from the left edge to the
# bottom edge, about the bottom-left corner: edges at 45 and 105 mm, dashes every 15 deg),
# tee (the straight road plus a branch down to the bottom edge), crossroads. A set is
# 2 straights, 4 curves, 1 tee, 1 crossroads.

t = 6 mm
thickness t

# a point on edge e (0 right, 1 top, 2 left, 3 bottom): `along` to the left of its centre
# seen from outside, `out` outward from the edge
def px(e, along, out) = (75 + out) * cos(e * 90 deg) - along * sin(e * 90 deg)
def py(e, along, out) = (75 + out) * sin(e * 90 deg) + along * cos(e * 90 deg)
dash_x = [-65.625, -46.875, 46.875, 65.625]

def road_tile(kind="straight") -> solid {
    body = RoundedRectangle(center=(0, 0), width=150, height=150, corner_radius=3)
    for e in range(4) {
        solid knob {
            neck = Rectangle(center=(px(e, 50, 4.5), py(e, 50, 4.5)), width=11, height=8,
                             rotation=e * 90 deg)
            ball = Circle(center=(px(e, 50, 10), py(e, 50, 10)), diameter=14)
        }
        hole socket {
            neck = Rectangle(center=(px(e, -50, -4.5), py(e, -50, -4.5)), width=11,
                             height=8.4, rotation=e * 90 deg, overrun=true)
            ball = Circle(center=(px(e, -50, -10), py(e, -50, -10)), diameter=14.4)
        }
    }
    drawing road {
        if kind == "straight" {
            top = Line((-75, 30), (75, 30))
            bottom = Line((-75, -30), (75, -30))
            # FIX after the first valid program: the straight lost the two dashes either
            # side of the zebra (I had reused the junction tiles' list): 28.125 mm out
            for x in dash_x + [-28.125, 28.125] {
                dash = Line((x - 5, 0), (x + 5, 0))
            }
            for k in range(6) {
                stripe = Rectangle(center=(-17.5 + 7 * k, 0), width=4, height=52, fill=true)
            }
        } elif kind == "curve" {
            inner = Arc(center=(-75, -75), radius=45, start_angle=0 deg, end_angle=90 deg)
            outer = Arc(center=(-75, -75), radius=105, start_angle=0 deg, end_angle=90 deg)
            for k in range(6) {
                dash = Arc(center=(-75, -75), radius=75, start_angle=k * 15 deg + 3.5 deg,
                           end_angle=k * 15 deg + 11.5 deg)
            }
        } elif kind == "tee" {
            top = Line((-75, 30), (75, 30))
            bottom_l = Line((-75, -30), (-30, -30))
            bottom_r = Line((30, -30), (75, -30))
            branch_l = Line((-30, -75), (-30, -30))
            branch_r = Line((30, -75), (30, -30))
            for x in dash_x {
                dash = Line((x - 5, 0), (x + 5, 0))
            }
            for y in [-65.625, -46.875] {
                branch_dash = Line((0, y - 5), (0, y + 5))
            }
        } else {
            for sx in [-1, 1] {
                for sy in [-1, 1] {
                    kerb_v = Line((sx * 30, sy * 75), (sx * 30, sy * 30))
                    kerb_h = Line((sx * 30, sy * 30), (sx * 75, sy * 30))
                }
            }
            for x in dash_x {
                dash = Line((x - 5, 0), (x + 5, 0))
                dash_v = Line((0, x - 5), (0, x + 5))
            }
        }
    }
}

assembly road_set {
    straight_a = road_tile(kind="straight")
    straight_b = road_tile(kind="straight")
    tee = road_tile(kind="tee")
    cross = road_tile(kind="cross")
    curve_a = road_tile(kind="curve")
    curve_b = road_tile(kind="curve")
    curve_c = road_tile(kind="curve")
    curve_d = road_tile(kind="curve")

    # flat: two rows of four
    RightOf(straight_b, straight_a, gap=6)
    AlignCenterY(straight_b, straight_a)
    RightOf(tee, straight_b, gap=6)
    AlignCenterY(tee, straight_b)
    RightOf(cross, tee, gap=6)
    AlignCenterY(cross, tee)
    Below(curve_a, straight_a, gap=6)
    AlignLeft(curve_a, straight_a)
    RightOf(curve_b, curve_a, gap=6)
    AlignCenterY(curve_b, curve_a)
    RightOf(curve_c, curve_b, gap=6)
    AlignCenterY(curve_c, curve_b)
    RightOf(curve_d, curve_c, gap=6)
    AlignCenterY(curve_d, curve_c)

    # the request's numbers (members of one tile, which move together)
    assert abs(straight_a.body.width - 150 mm) < 0.01 mm and abs(straight_a.body.height - 150 mm) < 0.01 mm, "150 mm tiles"
    assert abs(straight_a.knob[0].ball.center.y - straight_a.body.center.y - 50 mm) < 0.01 mm, "right edge: knob 50 mm left of centre seen from outside (up)"
    assert abs(straight_a.socket[0].ball.center.y - straight_a.body.center.y + 50 mm) < 0.01 mm, "right edge: socket 50 mm right (down)"
    assert abs(straight_a.knob[0].ball.center.x - straight_a.body.bb.right - 10 mm) < 0.01 mm, "ball 10 mm out"
    assert abs(straight_a.knob[0].ball.center.y - straight_a.socket[2].ball.center.y) < 0.01 mm, "a right-edge knob meets a left-edge socket"
    assert abs(straight_a.knob[3].ball.center.x - straight_a.socket[1].ball.center.x) < 0.01 mm, "a bottom-edge knob meets a top-edge socket"
    assert abs(straight_a.socket[1].ball.diameter - straight_a.knob[1].ball.diameter - 0.4 mm) < 0.001 mm, "0.2 mm looser all round"
    assert abs(straight_a.road.top.start.y - straight_a.road.bottom.start.y - 60 mm) < 0.01 mm, "road 60 mm wide"
    assert abs(curve_a.road.outer.radius - curve_a.road.inner.radius - 60 mm) < 0.01 mm, "curve 60 mm wide"
    assert len(straight_a.road.stripe) == 6, "six zebra stripes"
    assert len(straight_a.road.dash) == 6, "FIX: 8 dash places per tile, 2 under the zebra"
    assert abs(straight_a.road.stripe[1].center.x - straight_a.road.stripe[0].center.x - 7 mm) < 0.01 mm, "stripes 7 mm apart"
    assert abs(dash_x[1] - dash_x[0] - 18.75) < 0.001 and abs(150 - dash_x[3] + dash_x[0] - 18.75) < 0.001, "18.75 mm pitch across tiles"
    assert distance(straight_a.socket[0].ball, straight_a.road.bottom) >= 5 mm, "sockets clear of the road"
}
