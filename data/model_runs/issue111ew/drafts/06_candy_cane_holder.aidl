# Request (holidays): a Christmas-tree candy cane holder for the mantelpiece, 6 mm birch
# ply, two pieces. The tree: 340 mm tall, four tiers of branches, 268 mm across the lowest
# branch tips, standing on a pot 100 mm wide at the bottom. Each of the 8 branch tips has a
# 7 mm round notch in its upper edge, centred 10 mm in from the tip, for a mini candy cane's
# crook to hang in. A filled engraved star at the top, six engraved filled baubles 8 mm
# across on the branches, "NOEL" engraved in filled bold letters 14 mm high on the pot.
# The foot: a bar 200 x 40 with R6 corners and a 120 x 8 relief underneath, crossing the
# tree at the middle of its pot by a cross halving, each slot 20 mm deep (0.2 mm clearance),
# so both stand on the mantel.

import "std/joints.aidl"

units mm
thickness 6 mm

STEPS = [(0, 340), (28, 280), (52, 215), (76, 150)]
TIPS = [(50, 280), (78, 215), (106, 150), (134, 85)]

# the point d along the edge from tip b back toward a
def toward(a, b, d) = b + (a - b) * (d / norm(a - b))

assembly candy_cane_holder {
    solid tree {
        body = Polygon(mirror([(0, 340), (50, 280), (28, 280), (78, 215), (52, 215),
                               (106, 150), (76, 150), (134, 85), (45, 85), (50, 0)],
                              about="y"))
        axis = Line((0, 0), (0, 340), construction=true)
        hole notches_r {
            for i in range(4) {
                n = Circle(center=toward(STEPS[i], TIPS[i], 10 mm), diameter=7)
            }
        }
        notches_l = Mirrored(notches_r, about=axis)
        slot = cross_halving(depth=20 mm, thickness=6 mm, clearance=0.2 mm, rotation=180 deg,
                             cx=0 mm, cy=0 mm)
        drawing deco {
            star = Star(center=(0, 312), points=5, outer_radius=12, inner_radius=5, fill=true)
            b1 = Circle(center=(-18, 262), diameter=8, fill=true)
            b2 = Circle(center=(30, 200), diameter=8, fill=true)
            b3 = Circle(center=(-40, 180), diameter=8, fill=true)
            b4 = Circle(center=(10, 160), diameter=8, fill=true)
            b5 = Circle(center=(60, 120), diameter=8, fill=true)
            b6 = Circle(center=(-70, 110), diameter=8, fill=true)
        }
        drawing label {
            t = Text("NOEL", position=(0, 52), size=14, font="sans:Bold", valign="middle",
                     fill=true)
        }
    }

    solid foot {
        body = RoundedRectangle(center=(0, 20), width=200, height=40, corner_radius=6)
        hole relief { r = Rectangle(center=(0, 3), width=120, height=10) }
        slot = cross_halving(depth=20 mm, thickness=6 mm, clearance=0.2 mm, cx=0 mm, cy=40 mm)
    }

    # on the sheet
    RightOf(foot, tree, gap=10)
    AlignBottom(foot, tree)

    # on the mantel: the tree facing the room, the foot across its pot
    Place(tree, position=(0, 0, 0), face="front", up="up")
    Place(foot, position=(-3, -3, 0), face="right", up="up")

    assert tree.body.bb.height == 340 mm, "340 tall"
    assert tree.body.bb.width == 268 mm, "268 across the lowest tips"
    assert tree.body.points[9].x - tree.body.points[10].x == 100 mm, "pot 100 wide at the bottom"
    assert len(tree.notches_r.n) == 4 and tree.notches_r.n[0].diameter == 7 mm
    assert abs(distance(tree.notches_r.n[3].center, tree.body.points[7]) - 10 mm) < 0.01 mm,
        "notch 10 mm in from the tip"
    assert tree.slot.depth + foot.slot.depth == foot.body.height, "halvings meet"
    assert foot.body.width == 200 mm and foot.body.height == 40 mm
    assert foot.relief.r.width == 120 mm and foot.relief.r.bb.top - foot.body.bb.bottom == 8 mm
    assert distance(tree.label, tree.slot) >= 3 mm, "NOEL clear of the slot"
    assert distance(tree.notches_r, tree.deco) >= 3 mm and distance(tree.notches_l, tree.deco) >= 3 mm
}
