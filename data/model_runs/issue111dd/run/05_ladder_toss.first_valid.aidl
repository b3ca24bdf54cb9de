# Request (sport): a tabletop ladder toss (ladder golf) for the club bar, 6 mm ply.
# Two uprights 40 mm wide and 320 mm tall with a round top, each with three holes for 10 mm dowel
# rungs (10.3 mm holes) at 110, 200 and 290 mm above the table, the points engraved 14 mm above
# each hole: 1 bottom, 2 middle, 3 top. Each upright stands in a foot 200 x 40 mm with 8 mm rounded
# ends, cross-halved 20 + 20 mm at the foot's middle; a 120 x 8 mm relief under each foot's middle
# so it stands on its ends. The uprights stand 250 mm apart, centre to centre (rungs cut to 262).

import "std/joints.aidl"

thickness 6 mm

rung_h = [110, 200, 290]
post_x = 125 mm

def upright() -> solid {
    body = Rectangle(center=(0, 150), width=40, height=300)
    cap = Circle(center=(0, 300), radius=20)
    for i in range(3) {
        hole rung { c = Circle(center=(0, rung_h[i]), diameter=10.3) }
    }
    halving = cross_halving(depth=20 mm, thickness=6 mm, rotation=180 deg, cx=0 mm, cy=0 mm)
    drawing points {
        for i in range(3) {
            n = Text(str(i + 1), position=(0, rung_h[i] + 14), size=8, valign="middle")
        }
    }
}

def foot() -> solid {
    body = RoundedRectangle(center=(0, 20), width=200, height=40, corner_radius=8)
    halving = cross_halving(depth=20 mm, thickness=6 mm, cx=0 mm, cy=40 mm)
    hole relief { r = Rectangle(center=(0, 3), width=120, height=10) }
}

assembly ladder_toss {
    left_post = upright()
    right_post = upright()
    left_foot = foot()
    right_foot = foot()

    # on the sheet
    RightOf(right_post, left_post, gap=8)
    AlignBottom(right_post, left_post)
    RightOf(left_foot, right_post, gap=8)
    AlignBottom(left_foot, left_post)
    Above(right_foot, left_foot, gap=8)
    AlignLeft(right_foot, left_foot)

    # assembled: posts face the front, feet run front to back through their bottoms
    Place(left_post, position=(-post_x, 3 mm, 0), face="front", up="up")
    Place(right_post, position=(post_x, 3 mm, 0), face="front", up="up")
    Place(left_foot, position=(-post_x - 3 mm, 0, 0), face="right", up="up")
    Place(right_foot, position=(post_x - 3 mm, 0, 0), face="right", up="up")

    # the request's numbers
    assert left_post.body.bb.width == 40 mm, "uprights 40 wide"
    assert left_post.cap.top.y - left_post.body.bb.bottom == 320 mm, "uprights 320 tall"
    assert len(left_post.rung) == 3, "three rungs"
    assert left_post.rung[0].c.diameter == 10.3 mm, "10.3 mm rung holes"
    assert left_post.rung[0].c.center.y - left_post.body.bb.bottom == 110 mm, "bottom rung 110"
    assert left_post.rung[1].c.center.y - left_post.body.bb.bottom == 200 mm, "middle rung 200"
    assert left_post.rung[2].c.center.y - left_post.body.bb.bottom == 290 mm, "top rung 290"
    assert left_post.points.n[2].position.y - left_post.rung[2].c.center.y == 14 mm, "points 14 above"
    assert left_post.points.n[0].text == "1" and left_post.points.n[2].text == "3", "1 bottom, 3 top"
    assert left_foot.body.bb.width == 200 mm and left_foot.body.bb.height == 40 mm, "feet 200 x 40"
    assert left_post.halving.cut.bb.height == 20 mm and left_foot.halving.cut.bb.height == 20 mm, "halved 20 + 20"
    assert left_foot.relief.r.bb.top - left_foot.body.bb.bottom == 8 mm, "8 mm relief"
    assert left_foot.relief.r.bb.width == 120 mm, "120 mm relief"
    assert 2 * post_x == 250 mm, "posts 250 apart"
}
