# Request: a Halloween yard silhouette, a black cat with an arched back and a curled tail,
# cut from 6 mm exterior ply (painted black), about 320 mm long and 250 mm tall above the
# ground, on two pointed stakes 200 mm long (24 mm wide at the top) under its feet, cut in
# one piece with it. Legs 26 mm wide with round feet, 170 mm apart (centre to centre).
# Two slanted almond eyes 18 x 10 mm cut through, 28 mm apart, backed by a 3 mm yellow
# acrylic plate (64 x 28 mm, R8 corners) glued behind them, so they glow in a porch light.

units mm
thickness 6 mm

assembly yard_cat {
    solid cat {
        back_leg = Slot(start=(-85, 13), end=(-85, 115), width=26)
        front_leg = Slot(start=(85, 13), end=(85, 115), width=26)
        arch = Stroke(Arc(center=(0, 90), radius=90, start_angle=10 deg, end_angle=170 deg), width=56)
        head = Circle(center=(135, 150), radius=40)
        left_ear = Polygon([(108, 172), (112, 215), (135, 188)])
        right_ear = Polygon([(140, 189), (165, 212), (170, 165)])
        tail = Stroke(Spline([(-85, 110), (-130, 140), (-140, 200), (-115, 240), (-95, 235)]), width=16)
        back_stake = Polygon([(-97, 13), (-73, 13), (-85, -200)])
        front_stake = Polygon([(73, 13), (97, 13), (85, -200)])
        hole eyes {
            left = Ellipse(center=(122, 152), rx=9, ry=5, rotation=-20 deg)
            right = Ellipse(center=(150, 152), rx=9, ry=5, rotation=20 deg)
        }
        Fixed(head)
    }
    solid glow {
        thickness 3 mm
        plate = RoundedRectangle(center=(0, 0), width=64, height=28, corner_radius=8)
    }
    RightOf(glow, cat, gap=10)
    AlignBottom(glow, cat)

    Place(cat, position=(0, 6, 0), face="front", up="up")
    Place(glow, position=(136, 9, 152), face="front", up="up")

    # the request's numbers
    assert abs(cat.bb.width - 320 mm) <= 15 mm, "about 320 long"
    assert abs(max(cat.tail.bb.top, cat.left_ear.bb.top, cat.right_ear.bb.top) - 250 mm) <= 15 mm, "about 250 tall"
    assert cat.back_leg.bb.bottom == 0 mm and cat.front_leg.bb.bottom == 0 mm, "feet on the ground line"
    assert cat.back_stake.points[2].y == -200 mm and cat.front_stake.points[2].y == -200 mm, "stakes 200 into the ground"
    assert cat.back_stake.bb.width == 24 mm, "stakes 24 wide"
    assert cat.front_leg.start.x - cat.back_leg.start.x == 170 mm, "legs 170 apart"
    assert cat.front_leg.width == 26 mm, "legs 26 wide"
    assert cat.eyes.right.center.x - cat.eyes.left.center.x == 28 mm, "eyes 28 apart"
    assert cat.eyes.left.rx * 2 == 18 mm and cat.eyes.left.ry * 2 == 10 mm, "eyes 18 x 10"
    assert glow.plate.width >= cat.eyes.bb.width + 8 mm, "the plate covers the eyes, 4 mm each side"
    assert glow.plate.height >= cat.eyes.bb.height + 8 mm, "and above and below"
    assert distance(cat.eyes, cat.head) >= 0 mm, "eyes inside the head"
}
