# Request (holidays): a tabletop Easter egg tree (Ostereierbaum) in 4 mm birch ply to hang
# blown, painted eggs on. Two trees of the same outline, 300 mm tall and 220 mm across the
# crown, slot together crosswise (cross-halving, 0.2 mm clearance) and stand on a 180 mm
# round base. Each tree: a trunk 40 mm wide at the foot tapering to 20 mm at 130 mm, a 20 mm
# leader up to the rounded top, and four pairs of curving branches 9 mm wide leaving the
# leader at 130, 180, 225 and 262 mm, each ending in a 14 mm round tip with a 4 mm hole for
# an egg hook (8 per tree, 16 eggs). The trees stand in mortises in the base (0.2 mm over)
# on 4 mm tabs under the trunk; "HAPPY EASTER" is engraved (filled, bold, 9 mm) round the
# front of the base, reading the right way up.

units mm
t = 4 mm
thickness t

H = 300 mm
crown = 220 mm
base_d = 180 mm
fit = 0.2 mm
tip_r = 7 mm
ys = [130 mm, 180 mm, 225 mm, 262 mm]
spans = [crown / 2 - tip_r, 82 mm, 60 mm, 36 mm]       # tip centres from the middle
rises = [50 mm, 42 mm, 34 mm, 24 mm]

import "std/joints.aidl"

def tree(from_top=true) -> solid {
    trunk = Trapezoid(center=(0, 65), bottom_width=40, top_width=20, height=130)
    leader = Stroke(Line((0, 120), (0, H - 10 mm)), width=20)
    for j in range(4) {
        for i in range(2) {
            branch = Stroke(Spline([((2 * i - 1) * 8 mm, ys[j]),
                                    ((2 * i - 1) * spans[j] * 0.5, ys[j] + rises[j] * 0.45),
                                    ((2 * i - 1) * spans[j], ys[j] + rises[j])]), width=9)
            tip = Circle(center=((2 * i - 1) * spans[j], ys[j] + rises[j]), radius=tip_r)
        }
    }
    hole eyes {
        for j in range(4) {
            for i in range(2) {
                e = Circle(center=((2 * i - 1) * spans[j], ys[j] + rises[j]), diameter=4)
            }
        }
    }
    if from_top {
        # tree A: one 30 mm tab under the trunk, halving from the top
        foot = Rectangle(center=(0, -t / 2), width=30, height=t)
        x = cross_halving(depth=H / 2, thickness=t, clearance=fit, cx=0, cy=H)
    } else {
        # tree B: its halving opens under the trunk, so two 10 mm tabs either side of it
        foot_l = Rectangle(center=(-11, -t / 2), width=10, height=t)
        foot_r = Rectangle(center=(11, -t / 2), width=10, height=t)
        x = cross_halving(depth=H / 2, thickness=t, clearance=fit, rotation=180 deg,
                          cx=0, cy=0)
    }
}

assembly egg_tree {
    tree_a = tree(from_top=true)
    tree_b = tree(from_top=false)
    solid base {
        disc = Circle(center=(0, 0), diameter=base_d)
        hole mortises {
            a = Rectangle(center=(0, 0), width=30 + fit, height=t + fit)
            bl = Rectangle(center=(0, -11), width=t + fit, height=10 + fit)
            br = Rectangle(center=(0, 11), width=t + fit, height=10 + fit)
        }
        drawing greeting {
            ring = Circle(center=(0, 0), radius=72, construction=true)
            g = Text("HAPPY EASTER", along=ring, size=9, font="sans:Bold", fill=true,
                     flip=true)
        }
    }

    # flat on the sheet
    RightOf(tree_b, tree_a, gap=8)
    AlignBottom(tree_b, tree_a)
    RightOf(base, tree_b, gap=8)
    AlignBottom(base, tree_b)

    # assembled: A across (x), B front to back (y), both standing on the base's top face
    Place(base, position=(0, 0, 0), face="up")
    Place(tree_a, position=(0, t / 2, t), face="front", up="up")
    Place(tree_b, position=(-t / 2, 0, t), face="right", up="up")

    assert tree_a.leader.bb.top == 300 mm, "300 mm tall"
    assert tree_a.bb.width == 220 mm and tree_b.bb.width == 220 mm, "220 mm across the crown"
    assert len(tree_a.eyes.e) * len(tree_a.eyes.e[0]) == 8, "8 eggs per tree"
    assert tree_a.x.depth + tree_b.x.depth == 300 mm, "the halvings meet"
    assert base.disc.diameter == 180 mm, "180 mm base"
    assert distance(base.greeting.g, base.mortises) >= 20 mm, "greeting clear of the mortises"
    for j in range(4) {
        assert distance(tree_a.eyes.e[j][0], tree_a.eyes.e[j][1]) >= 50 mm,
            "egg hooks far enough apart for eggs"
    }
}
