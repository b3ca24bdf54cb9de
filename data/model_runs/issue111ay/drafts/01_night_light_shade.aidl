# Request (home): a night-light shade for my son's bedroom, to stand over a battery LED tea
# light on his shelf. A square lantern 80 x 80 mm outside and 120 mm tall from 3 mm birch ply,
# open at top and bottom: four walls finger-jointed at the corners (10 mm fingers). The back
# and the two side walls each have six star cut-outs (5 points, 18 mm across the tips) in
# 2 columns x 3 rows, 30 mm apart across and 32 mm apart up. The front wall has his name
# "NOAH" cut through in bold stencil letters 20 mm tall across its middle, with one star
# centred 38 mm above and one 38 mm below the name's middle.

units mm
thickness 3 mm

import "std/joints.aidl"

param side = 80 mm, min = 60 mm, max = 120 mm
param tall = 120 mm, min = 90 mm, max = 200 mm
param star_r = 9 mm, min = 6 mm, max = 12 mm

def star_wall(edge="fingers") -> solid {
    p = finger_panel(width=side, height=tall, thickness=3 mm, finger=10 mm,
                     bottom="flat", top="flat", left=edge, right=edge)
    hole star {
        s = Star(center=(-15, -32), points=5, outer_radius=star_r, inner_radius=star_r * 0.45)
    }
    stars = GridPattern(star, 3, 2, (30, 32))
}

assembly lantern {
    solid front {
        p = finger_panel(width=side, height=tall, thickness=3 mm, finger=10 mm,
                         bottom="flat", top="flat", left="fingers", right="fingers")
        hole name {
            # FIX after the first valid program: at 20 mm the name was wider than the wall and
            # its N and H ran out through the finger-jointed edges (no message said so); kept
            # within 60 mm of the 74 mm between the joints
            t = Text("NOAH", position=(0, 0), size=20, font="sans:Bold", valign="middle",
                     stencil=true, max_width=60 mm)
        }
        hole upper {
            s = Star(center=(0, 38), points=5, outer_radius=star_r, inner_radius=star_r * 0.45)
        }
        hole lower {
            s = Star(center=(0, -38), points=5, outer_radius=star_r, inner_radius=star_r * 0.45)
        }
        assert upper.s.center.y - name.t.position.y == 38 mm, "star 38 mm above the name"
        assert name.t.position.y - lower.s.center.y == 38 mm, "star 38 mm below the name"
        assert name.bb.width <= 60 mm and name.bb.left > p.outline.bb.left + 3 mm + 4 mm,
            "the name stays clear of the finger joints"
    }
    back = star_wall(edge="fingers")
    left = star_wall(edge="slots")
    right = star_wall(edge="slots")

    # laid out flat in a row for cutting
    RightOf(back, front, gap=6)
    RightOf(left, back, gap=6)
    RightOf(right, left, gap=6)
    AlignCenterY(back, front)
    AlignCenterY(left, front)
    AlignCenterY(right, front)

    # stood up into the lantern for the assembled view
    Place(front, position=(0, -37, 60), rotation=(90 deg, 0, 0))
    Place(back, position=(0, 40, 60), rotation=(90 deg, 0, 0))
    Place(left, position=(-40, 0, 60), rotation=(90 deg, 0, 90 deg))
    Place(right, position=(37, 0, 60), rotation=(90 deg, 0, 90 deg))

    assert front.p.outline.width == 80 mm and front.p.outline.height == 120 mm
    assert len(back.stars) == 6 and len(left.stars) == 6 and len(right.stars) == 6
    assert back.stars[1].s.center.x - back.stars[0].s.center.x == 30 mm
    assert back.stars[2].s.center.y - back.stars[0].s.center.y == 32 mm
    assert 2 * back.star.s.outer_radius == 18 mm, "18 mm across the tips"
}
