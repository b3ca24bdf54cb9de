# Request: a tabletop Halloween tree, 3 mm black-stained ply. Two identical bare-tree
# silhouettes crossed at right angles (cross-halved, 0.15 mm clearance): a tapering trunk
# 44 mm wide at the foot, 14 at the top, 260 mm tall, with crooked branches 9, 8, 7 and 6 mm
# thick and 5 mm twigs, six of their tips ending in 9 mm round eyelets with 2.5 mm holes to
# hang ornaments from. Each trunk stands on two 10 mm tenons in a 150 mm round base (0.15 mm
# clearance), which has "HAPPY HALLOWEEN" engraved over the top and "31 OCTOBER" under the
# bottom, 7 mm tall, along a 124 mm circle. Two ornaments to hang: a bat 60 mm across and a
# jack-o'-lantern 40 x 32 mm with its eyes and mouth cut out, each with a 2.5 mm hanging hole.

import "std/joints.aidl"

thickness 3 mm

trunk_h = 260 mm
hang = [(95, 175), (75, 245), (95, 125), (-80, 205), (-100, 170), (-55, 270)]

# one silhouette: the foot's shoulders on y = 0, tenon tips at y = -3; upper=true: the
# halving runs down from the top of the trunk, else up from the foot
def tree_panel(upper=true) -> solid {
    trunk = Trapezoid(center=(0, trunk_h / 2), bottom_width=44, top_width=14,
                      height=trunk_h)
    foot = Rectangle(bottom_left=(-22, -3), width=44, height=3)
    r1 = Stroke(Spline([(8, 110), (45, 140), (70, 150), (95, 175)]), width=9)
    r1t = Stroke(Spline([(60, 147), (75, 132), (95, 125)]), width=5)
    r2 = Stroke(Spline([(6, 170), (35, 195), (50, 225), (75, 245)]), width=8)
    r2t = Stroke(Spline([(42, 208), (62, 205), (80, 215)]), width=5)
    r3 = Stroke(Spline([(4, 225), (20, 250), (30, 280)]), width=6)
    l1 = Stroke(Spline([(-8, 130), (-40, 150), (-65, 175), (-80, 205)]), width=9)
    l1t = Stroke(Spline([(-55, 163), (-80, 160), (-100, 170)]), width=5)
    l2 = Stroke(Spline([(-6, 190), (-30, 215), (-45, 245), (-55, 270)]), width=7)
    l2t = Stroke(Spline([(-38, 230), (-52, 228), (-62, 234)]), width=5)
    for i in range(len(hang)) {
        eyelet = Circle(center=hang[i], diameter=9)
    }
    hole eyes {
        for i in range(len(hang)) {
            e = Circle(center=hang[i], diameter=2.5)
        }
    }
    feet = tab_and_slot(part="tab", length=44 mm, thickness=3 mm, tabs=2, tab=10 mm,
                        screw=0, rotation=180 deg, cx=0 mm, cy=-3 mm)
    if upper {
        halve = cross_halving(depth=trunk_h - 150 mm, thickness=3 mm, clearance=0.15 mm,
                              cx=0 mm, cy=trunk_h)
    } else {
        halve = cross_halving(depth=150 mm, thickness=3 mm, clearance=0.15 mm,
                              rotation=180 deg, cx=0 mm, cy=0 mm)
    }
}

assembly spooky_tree {
    tree_a = tree_panel(upper=true)
    tree_b = tree_panel(upper=false)

    solid base {
        disc = Circle(center=(0, 0), diameter=150)
        hole mortise {
            a = tab_and_slot(part="slot", length=44 mm, thickness=3 mm, tabs=2, tab=10 mm,
                             screw=0, clearance=0.15 mm, cx=0 mm, cy=0 mm)
            b = tab_and_slot(part="slot", length=44 mm, thickness=3 mm, tabs=2, tab=10 mm,
                             screw=0, clearance=0.15 mm, rotation=90 deg, cx=0 mm, cy=0 mm)
        }
        drawing words {
            rim = Circle(center=(0, 0), diameter=124, construction=true)
            top = Text("HAPPY HALLOWEEN", along=rim, size=7, valign="middle")
            bottom = Text("31 OCTOBER", along=rim, size=7, valign="middle", flip=true)
        }
    }

    solid bat {
        wings = Polygon([(0, 6), (3, 10), (5, 5), (12, 6), (22, 12), (30, 8), (26, 4),
                         (28, -2), (22, 0), (18, -5), (13, -1), (7, -4), (3, -8), (0, -6)],
                        mirror="y")
        hole hang_hole { c = Circle(center=(0, 1), diameter=2.5) }
    }

    solid pumpkin {
        middle = Ellipse(center=(0, 0), rx=20, ry=16)
        left = Ellipse(center=(-8, 0), rx=12, ry=15)
        right = Ellipse(center=(8, 0), rx=12, ry=15)
        stem = Rectangle(center=(0, 17), width=6, height=8)
        hole face {
            eye_l = Triangle(center=(-7, 3), base=7, height=6)
            eye_r = Triangle(center=(7, 3), base=7, height=6)
            mouth = Polygon([(-12, -4), (-8, -7), (-4, -4), (0, -8), (4, -4), (8, -7),
                             (12, -4), (8, -11), (-8, -11)])
        }
        hole hang_hole { c = Circle(center=(0, 11), diameter=2.5) }
    }

    # on the sheet
    RightOf(tree_b, tree_a, gap=10)
    AlignBottom(tree_b, tree_a)
    RightOf(base, tree_b, gap=10)
    AlignBottom(base, tree_b)
    Above(bat, base, gap=10)
    AlignLeft(bat, base)
    Above(pumpkin, bat, gap=10)
    AlignLeft(pumpkin, bat)

    # assembled: the base on z = 0, tree a along x, tree b along y, the ornaments hanging
    # 25 mm under the eyelets at (95, 125) and (-100, 170) of tree a
    # FIX after the first valid program: hung from (95, 175) and (-80, 205), the bat and
    # the pumpkin ran into the twigs below those eyelets (W0517, 3 mm deep); the twig tips
    # at (95, 125) and (-100, 170) have nothing under them
    Place(base, position=(0, 0, 0), face="up")
    Place(tree_a, position=(0, 1.5, 3), face="front", up="up")
    Place(tree_b, position=(-1.5, 0, 3), face="right", up="up")
    Place(bat, position=(95, 1.5, 3 + 125 - 25), face="front", up="up")
    Place(pumpkin, position=(-100, 1.5, 3 + 170 - 25 - 11), face="front", up="up")

    assert tree_a.trunk.height == 260 mm, "a 260 mm trunk"
    assert tree_a.trunk.bottom_width == 44 mm and tree_a.trunk.top_width == 14 mm,
        "trunk 44 to 14 mm"
    assert tree_a.halve.depth + tree_b.halve.depth == 260 mm, "the halvings meet"
    assert len(tree_a.eyes.e) == 6, "six eyelets"
    assert base.disc.diameter == 150 mm, "a 150 mm base"
    assert bat.bb.width == 60 mm, "a 60 mm bat"
    assert pumpkin.bb.width == 40 mm, "a 40 mm pumpkin"
    assert distance(base.words, base.mortise) >= 5 mm, "the words clear of the mortises"
}
