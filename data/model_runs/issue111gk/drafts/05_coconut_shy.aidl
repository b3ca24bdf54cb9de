# Request: a tabletop coconut shy for a children's party, 6 mm ply. A base board 450 x 140 mm
# (R10 corners) with three posts 150 mm apart on its centre line, 150, 250 and 200 mm tall
# (left to right). Each post is two 70 mm wide panels cross-halved into a "+" (0.2 mm
# clearance), standing on two 10 mm tenons each in mortises in the base (0.2 mm clearance);
# the top of each panel has a round cradle notch 12 mm deep (radius 33) so a 65 mm ball sits
# in the four notches. "COCONUT SHY" in 14 mm filled bold letters engraved along the back of
# the base, and the score of each post (10, 50, 20) in 16 mm filled figures in front of it.

import "std/joints.aidl"

thickness 6 mm

scores = [10, 50, 20]
heights = [150 mm, 250 mm, 200 mm]

# one panel of a post: shoulders at y = 0, tenon tips at y = -6; upper=true: the halving
# runs down from the cradle, else up from the bottom
def post_panel(h=150 mm, upper=true) -> solid {
    body = Rectangle(bottom_left=(-35, -6), width=70, height=h + 6 mm)
    feet = tab_and_slot(part="tab", length=70 mm, thickness=6 mm, tabs=2, tab=10 mm,
                        screw=0, rotation=180 deg, cx=0 mm, cy=-6 mm)
    hole cradle { c = Circle(center=(0, h + 33 mm - 12 mm), radius=33) }
    if upper {
        halve = cross_halving(depth=h / 2 - 12 mm, thickness=6 mm, clearance=0.2 mm,
                              cx=0 mm, cy=h - 12 mm)
    } else {
        halve = cross_halving(depth=h / 2, thickness=6 mm, clearance=0.2 mm,
                              rotation=180 deg, cx=0 mm, cy=0 mm)
    }
}

assembly coconut_shy {
    solid base {
        body = RoundedRectangle(center=(0, 0), width=450, height=140, corner_radius=10)
        hole mortise {
            a = tab_and_slot(part="slot", length=70 mm, thickness=6 mm, tabs=2, tab=10 mm,
                             screw=0, clearance=0.2 mm, cx=-150 mm, cy=0 mm)
            b = tab_and_slot(part="slot", length=70 mm, thickness=6 mm, tabs=2, tab=10 mm,
                             screw=0, clearance=0.2 mm, rotation=90 deg, cx=-150 mm,
                             cy=0 mm)
        }
        row = LinearPattern(mortise, 3, (150, 0))
        drawing title {
            t = Text("COCONUT SHY", position=(0, 45), size=14, font="sans:Bold",
                     valign="middle", fill=true)
        }
        drawing score {
            for i in range(3) {
                t = Text(str(scores[i]), position=(-150 + i * 150, -45), size=16,
                         font="sans:Bold", valign="middle", fill=true)
            }
        }
    }

    left_a = post_panel(h=heights[0], upper=true)
    left_b = post_panel(h=heights[0], upper=false)
    mid_a = post_panel(h=heights[1], upper=true)
    mid_b = post_panel(h=heights[1], upper=false)
    right_a = post_panel(h=heights[2], upper=true)
    right_b = post_panel(h=heights[2], upper=false)

    # on the sheet: the panels in a row under the base
    Below(left_a, base, gap=10)
    AlignLeft(left_a, base)
    RightOf(left_b, left_a, gap=8)
    AlignTop(left_b, left_a)
    RightOf(mid_a, left_b, gap=8)
    AlignTop(mid_a, left_b)
    RightOf(mid_b, mid_a, gap=8)
    AlignTop(mid_b, mid_a)
    RightOf(right_a, mid_b, gap=8)
    AlignTop(right_a, mid_b)
    RightOf(right_b, right_a, gap=8)
    AlignTop(right_b, right_a)

    # assembled: the base on z = 0, each "+" on its mortises, the a panels along x
    Place(base, position=(0, 0, 0), face="up")
    Place(left_a, position=(-150, 3, 6), face="front", up="up")
    Place(left_b, position=(-150 - 3, 0, 6), face="right", up="up")
    Place(mid_a, position=(0, 3, 6), face="front", up="up")
    Place(mid_b, position=(-3, 0, 6), face="right", up="up")
    Place(right_a, position=(150, 3, 6), face="front", up="up")
    Place(right_b, position=(150 - 3, 0, 6), face="right", up="up")

    assert base.body.bb.width == 450 mm and base.body.bb.height == 140 mm, "450 x 140 base"
    assert len(base.row) == 3, "three posts"
    assert left_a.body.bb.height - 6 mm == 150 mm, "left post 150 tall"
    assert mid_a.body.bb.height - 6 mm == 250 mm, "middle post 250 tall"
    assert right_a.body.bb.height - 6 mm == 200 mm, "right post 200 tall"
    assert left_a.body.bb.width == 70 mm, "70 mm panels"
    assert mid_a.body.bb.top - mid_a.cradle.c.bottom.y == 12 mm, "cradle 12 mm deep"
    assert mid_a.cradle.c.radius * 2 >= 65 mm, "a 65 mm ball fits the cradle"
    assert left_a.halve.depth + left_b.halve.depth == 150 mm - 12 mm,
        "the halvings meet (left)"
    assert mid_a.halve.depth + mid_b.halve.depth == 250 mm - 12 mm, "the halvings meet (mid)"
    assert right_a.halve.depth + right_b.halve.depth == 200 mm - 12 mm,
        "the halvings meet (right)"
    assert base.title.t.size == 14 mm, "14 mm title"
}
