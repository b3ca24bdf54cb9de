# Request (holidays): a yule-log tealight centrepiece for the Christmas table, 6 mm ply. Two
# glued layers, each a round-ended log 360 x 90 mm seen from above. The top layer has three
# 40 mm holes for tealights on the centre line, 90 mm apart (the bottom layer closes them
# into 6 mm pockets), four wavy bark lines engraved along the log and two engraved knots. At
# each end a holly sprig stands across the log: two 72 mm holly leaves with three spikes a
# side, leaning 30 deg either side of upright, and three 10 mm berries where they meet; it
# stands on a 16 mm wide tab glued into a slot in the top layer (0.1 mm clearance), the slot's
# middle 20 mm in from the log's end.

thickness 6 mm

t = 6 mm
log_len = 360 mm
log_w = 90 mm
pitch = 90 mm
tab_w = 16 mm
sprig_x = log_len / 2 - 20 mm

# a holly leaf's half outline, stem at (0, 0), tip at (72, 0); turned by a about the stem
# and lifted to the sprig's crown
half_leaf = [(0, 0), (12, 13), (20, 8), (32, 15), (40, 9), (52, 11), (60, 5), (72, 0)]
def turn(p, a) = (p[0] * cos(a) - p[1] * sin(a), p[0] * sin(a) + p[1] * cos(a) + 14 mm)

def log_layer() -> solid {
    body = Slot(center=(0, 0), length=log_len, width=log_w)
}

def sprig() -> solid {
    stem = Rectangle(bottom_left=(-tab_w / 2, 0), width=tab_w, height=16 mm)
    right_leaf = Spline([turn(p, 60 deg) for p in mirror(half_leaf, about="x")], closed=true,
                        corners=[0, 1, 3, 5, 7, 9, 11, 13])
    left_leaf = Spline([turn(p, 120 deg) for p in mirror(half_leaf, about="x")], closed=true,
                       corners=[0, 1, 3, 5, 7, 9, 11, 13])
    b1 = Circle(center=(-5 mm, 16 mm), diameter=10 mm)
    b2 = Circle(center=(5 mm, 16 mm), diameter=10 mm)
    b3 = Circle(center=(0, 24 mm), diameter=10 mm)
}

assembly yule_log {
    bottom = log_layer()

    solid top {
        body = Slot(center=(0, 0), length=log_len, width=log_w)
        hole lights {
            for i in range(3) {
                c = Circle(center=((i - 1) * pitch, 0), diameter=40 mm)
            }
        }
        hole slots {
            l = Rectangle(center=(-sprig_x, 0), width=t + 0.1 mm, height=tab_w + 0.1 mm)
            r = Rectangle(center=(sprig_x, 0), width=t + 0.1 mm, height=tab_w + 0.1 mm)
        }
        drawing bark {
            a = Spline([(-150, 30), (-100, 34), (-50, 29), (0, 33), (50, 29), (100, 34), (150, 30)])
            b = Spline([(-150, -30), (-100, -34), (-50, -29), (0, -33), (50, -29), (100, -34), (150, -30)])
            c = Spline([(-135, 39), (-80, 41), (-20, 38), (40, 41), (100, 39), (135, 40)])
            d = Spline([(-135, -40), (-80, -38), (-20, -41), (40, -38), (100, -41), (135, -39)])
            k1 = Ellipse(center=(-45, 18), rx=7, ry=3.5)
            k1i = Ellipse(center=(-45, 18), rx=3, ry=1.5)
            k2 = Ellipse(center=(45, -18), rx=6, ry=3)
            k2i = Ellipse(center=(45, -18), rx=2.5, ry=1.2)
        }
    }

    left_sprig = sprig()
    right_sprig = sprig()

    # on the sheet
    Above(top, bottom, gap=10)
    Above(left_sprig, top, gap=10)
    RightOf(right_sprig, left_sprig, gap=10)
    AlignBottom(right_sprig, left_sprig)

    # in 3D: the bottom layer on z = 0, the top on it, the sprigs across the log in the slots
    Place(bottom, position=(0, 0, 0))
    Place(top, position=(0, 0, t))
    Place(left_sprig, position=(-sprig_x - t / 2, 0, t), face="right", up="up")
    Place(right_sprig, position=(sprig_x - t / 2, 0, t), face="right", up="up")

    assert bottom.body.length == 360 mm and bottom.body.width == 90 mm, "log 360 x 90"
    assert len(top.lights.c) == 3, "three tealights"
    assert top.lights.c[0].diameter == 40 mm, "40 mm holes"
    assert top.lights.c[1].center.x - top.lights.c[0].center.x == 90 mm, "90 mm apart"
    assert top.body.bb.right - top.slots.r.center.x == 20 mm, "slot 20 mm in from the end"
    assert left_sprig.stem.width == 16 mm, "16 mm tab"
    assert left_sprig.b1.diameter == 10 mm, "10 mm berries"
}
