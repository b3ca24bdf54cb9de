# Request (science): a brachistochrone race for two 16 mm marbles, 3 mm ply. Two tracks side
# by side from the same start height to the same finish, 160 mm lower and 251.3 mm on
# (pi x 80): one a straight ramp, the other the cycloid x = r(t - sin t), y = -r(1 - cos t),
# r = 80 mm, t from 0 to pi. Each track is a pair of profile ribs whose top edges carry the
# marble, 8 mm apart inside; a rib is 25 mm tall at the finish, has a 28 mm flat start with a
# 12 mm wide post rising 20 mm behind it, and a 60 mm flat run-out with a 12 mm end post.
# Each rib stands on three 15 mm tabs glued into a 400 x 120 base and has three 6 mm holes
# 12 mm above its bottom for spacer dowels. "CYCLOID" / "STRAIGHT" engraved on the outer
# ribs, "BRACHISTOCHRONE" along the base's front edge. Five parts.

import "std/joints.aidl"

units mm
thickness 3 mm

t = 3 mm
r = 80 mm
N = 60
run = pi * r
drop = 2 * r
y_b = -drop - 25 mm
x0 = -40 mm
x1 = run + 72 mm
mid_x = (x0 + x1) / 2
rib_len = x1 - x0
gap_in = 8 mm

cyc = [(r * (i * pi / N - sin(i * pi / N)), -r * (1 - cos(i * pi / N))) for i in range(N + 1)]
straight = [(0, 0), (run, -drop)]

# FIX after the first valid program: s = -1 draws the rib mirrored, for a back rib placed
# facing "back" so that its engraving faces out (the cycloid's label was on its inner rib,
# facing the other track, where nobody sees it)
def rib(curve, name, s) -> solid {
    pts = ([(x0, y_b), (x0, 20), (x0 + 12, 20), (x0 + 12, 0)] + curve +
           [(run + 60, -drop), (run + 60, -drop + 20), (x1, -drop + 20), (x1, y_b)])
    profile = Polygon([(s * p[0], p[1]) for p in pts])
    feet = tab_and_slot(part="tab", length=rib_len, thickness=t, tabs=3, tab=15, screw=0,
                        rotation=180 deg, cx=s * mid_x, cy=y_b)
    hole dowels {
        a = Circle(center=(0, y_b + 12), diameter=6)
        b = Circle(center=(s * run / 2, y_b + 12), diameter=6)
        c = Circle(center=(s * (run + 30), y_b + 12), diameter=6)
    }
    drawing label {
        word = Text(name, (s * 60, y_b + 40), size=8)
    }
}

def track_y(k) = 25 mm if k == 0 else -25 mm

assembly race {
    solid base {
        plate = RoundedRectangle(center=(mid_x, 0), width=400, height=120, corner_radius=6)
        for k in range(2) {
            inner = tab_and_slot(part="slot", length=rib_len, thickness=t, tabs=3, tab=15,
                                 screw=0, clearance=0.1, cx=mid_x, cy=track_y(k) + (gap_in + t) / 2)
            outer = tab_and_slot(part="slot", length=rib_len, thickness=t, tabs=3, tab=15,
                                 screw=0, clearance=0.1, cx=mid_x, cy=track_y(k) - (gap_in + t) / 2)
        }
        drawing title {
            word = Text("BRACHISTOCHRONE", (mid_x, -52), size=8)
        }
    }

    cyc_back = rib(cyc, "CYCLOID", -1)
    cyc_front = rib(cyc, "", 1)
    line_back = rib(straight, "", 1)
    line_front = rib(straight, "STRAIGHT", 1)

    # 3D: the cycloid pair at y = +25, the straight pair at y = -25, engraving facing front
    Place(base, position=(0, 0, 0))
    Place(cyc_back, position=(0, 25 mm + (gap_in + t) / 2 - t / 2, -y_b), face="back", up="up")
    Place(cyc_front, position=(0, 25 mm - (gap_in + t) / 2 + t / 2, -y_b), face="front", up="up")
    Place(line_back, position=(0, -25 mm + (gap_in + t) / 2 + t / 2, -y_b), face="front", up="up")
    Place(line_front, position=(0, -25 mm - (gap_in + t) / 2 + t / 2, -y_b), face="front", up="up")

    # on the sheet
    Above(cyc_back, base, gap=5)
    Above(cyc_front, cyc_back, gap=5)
    # FIX after the first valid program: RightOf alone left the straight ribs on the base (W0511)
    RightOf(line_back, cyc_back, gap=5)
    AlignBottom(line_back, cyc_back)
    RightOf(line_front, cyc_front, gap=5)
    AlignBottom(line_front, cyc_front)

    assert abs(cyc[N][0] - 251.3 mm) < 0.1 mm, "cycloid run pi x 80"
    assert cyc[N][1] == -160 mm and straight[1][1] == -160 mm, "both drop 160"
    assert cyc[N][0] == straight[1][0], "same finish"
    assert base.plate.bb.width == 400 mm and base.plate.bb.height == 120 mm, "base 400 x 120"
    assert cyc_front.profile.bb.top - y_b == 20 mm + 160 mm + 25 mm, "start post 20 above the start"
}
