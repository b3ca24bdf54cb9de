# Request: a Thanksgiving gratitude tree for the table, cut from 3 mm ply. A flat bare tree:
# a trunk tapering from 44 mm at the ground to 14 mm at a rounded top 240 mm up, on a foot
# 130 mm wide and 15 mm tall; three branches each side, 8 mm wide, bent once, leaving the trunk
# at 70, 115 and 160 mm and ending in round buds of 12 mm at (85, 135), (65, 185) and
# (35, 225) mm (and mirrored); a 3 mm hole in each bud and one 4 mm below the top of the trunk
# to tie the leaves on. It stands in a crossbar foot 120 x 40 mm with its top corners rounded
# 15 mm, the two cross-halved 20 mm each at the trunk's centre. Three leaf tags, lens-shaped,
# 44 mm long and 22 mm wide, with a 3 mm hole 6 mm from one tip, engraved "FAMILY", "FRIENDS"
# and "HOME" in 4 mm letters; they hang 10 mm below a bud each.

import "std/joints.aidl"

thickness 3 mm

param trunk_h = 240 mm, min = 180 mm, max = 300 mm
t = 3 mm
branches = [[(0, 70), (45, 95), (85, 135)],
            [(0, 115), (40, 140), (65, 185)],
            [(0, 160), (25, 185), (35, 225)]]

def leaf(word="THANKS") -> solid {
    lens = Intersect(Circle(center=(0, 16.5), radius=27.5), Circle(center=(0, -16.5), radius=27.5))
    hole eye {
        c = Circle(center=(-16, 0), diameter=3)
    }
    drawing label {
        w = Text(word, position=(4, 0), size=4, valign="middle")
    }
}

assembly gratitude_tree {
    solid tree {
        foot = Trapezoid(center=(0, 7.5), bottom_width=130, top_width=44, height=15)
        trunk = Trapezoid(center=(0, 10 + (trunk_h - 10) / 2), bottom_width=44, top_width=14,
                          height=trunk_h - 10)
        crown = Circle(center=(0, trunk_h), radius=7)
        for sgn in [-1, 1] {
            for k in range(3) {
                b = Stroke(Polyline([(sgn * p[0], p[1]) for p in branches[k]]), 8)
                bud = Circle(center=(sgn * branches[k][2][0], branches[k][2][1]), diameter=12)
            }
        }
        hole ties {
            for sgn in [-1, 1] {
                for k in range(3) {
                    c = Circle(center=(sgn * branches[k][2][0], branches[k][2][1]), diameter=3)
                }
            }
            top = Circle(center=(0, trunk_h - 4), diameter=3)
        }
        slot = cross_halving(depth=20 mm, thickness=t, rotation=180 deg, cx=0 mm, cy=0 mm)
    }
    solid crossbar {
        bar = RoundedRectangle(bottom_left=(-60, 0), width=120, height=40, corner_radii=[15, 15, 0, 0])
        slot = cross_halving(depth=20 mm, thickness=t, cx=0 mm, cy=40 mm)
    }
    family = leaf(word="FAMILY")
    friends = leaf(word="FRIENDS")
    home = leaf(word="HOME")

    Place(tree, position=(0, t / 2, 0), face="front", up="up")
    Place(crossbar, position=(-t / 2, 0, 0), face="right", up="up")
    # each leaf hangs from a bud, its hole up, 10 mm below the bud, just in front of the tree
    Place(family, position=(85, -2 * t, 135 - 10 - 16), face="front", up="right")
    Place(friends, position=(-65, -2 * t, 185 - 10 - 16), face="front", up="right")
    Place(home, position=(35, -2 * t, 225 - 10 - 16), face="front", up="right")

    # on the sheet
    RightOf(crossbar, tree, gap=8)
    AlignBottom(crossbar, tree)
    Above(family, crossbar, gap=8)
    AlignLeft(family, crossbar)
    Above(friends, family, gap=6)
    AlignLeft(friends, family)
    Above(home, friends, gap=6)
    AlignLeft(home, friends)

    assert tree.foot.bb.width == 130 mm and tree.foot.bb.height == 15 mm, "foot 130 x 15"
    assert tree.crown.center.y - tree.foot.bb.bottom == 240 mm, "trunk top 240 mm up"
    assert len(tree.bud) == 2 and len(tree.bud[0]) == 3, "three branches a side"
    assert tree.bud[1][0].center.x - tree.trunk.center.x == 85 mm, "lowest bud 85 mm out"
    assert tree.ties.c[0][0].diameter == 3 mm, "3 mm tie holes"
    assert crossbar.bar.bb.width == 120 mm and crossbar.bar.bb.height == 40 mm, "crossbar 120 x 40"
    assert tree.slot.depth + crossbar.slot.depth == crossbar.bar.bb.height, "halvings meet"
    assert family.lens.bb.width == 44 mm and family.lens.bb.height == 22 mm, "leaf 44 x 22"
    assert family.eye.c.center.x - family.lens.bb.left == 6 mm, "hole 6 mm from the tip"
    assert distance(family.label, family.eye) >= 2 mm, "word clear of the hole"
    assert distance(friends.label.w, friends.lens) >= 0.5 mm, "the longest word inside its leaf"
}
