# Request (parties): a "HAPPY 40" cake topper cut from 3 mm gold mirror acrylic, one piece:
# "HAPPY" in bold sans, 24 mm cap height, on a 4 mm rail as wide as the word; below it a
# big "40" in bold sans, 50 mm high, hanging from that rail and standing on a 4 mm base
# rail running from star to star; a five-point star (outer radius 12 mm, inner 5 mm, tips
# rounded R1) standing on the base rail on each side of "40", 6 mm clear of it (first
# written: 14 mm clear and the rail as wide as "HAPPY": the assert on 140 mm failed at
# 143 mm and W0504 found the stars off the rail's ends); two stakes 8 mm
# wide at the top, 2 mm at the tip, reaching 85 mm below the base rail, 50 mm apart
# (centres), to push into the cake. Overall no wider than 140 mm.

units mm
thickness 3 mm

rail_h = 4 mm

solid topper {
    happy = Text("HAPPY", position=(0, 0), size=24, font="sans:Bold")
    top_rail = Rectangle(center=(happy.center.x, -1), width=happy.bb.width, height=rail_h)

    age = Text("40", position=(0, -1), size=50, font="sans:Bold", valign="top")
    base_rail = Rectangle(center=(happy.center.x, -1 - 50 - 1), width=100, height=rail_h)

    star_l = Star(center=(-40, -40), points=5, outer_radius=12, inner_radius=5, tip_radius=1)
    star_r = Star(center=(40, -40), points=5, outer_radius=12, inner_radius=5, tip_radius=1)
    Above(star_l, base_rail, gap=-1)
    Above(star_r, base_rail, gap=-1)
    LeftOf(star_l, age, gap=6)
    RightOf(star_r, age, gap=6)
    # the base rail runs from star to star
    AlignLeft(base_rail, star_l)
    AlignRight(base_rail, star_r)

    for k in range(2) {
        stake = Polygon([(-4, 0), (4, 0), (1, -85 - 2), (-1, -85 - 2)])
    }
    # the stakes start 2 mm inside the base rail and reach 85 mm below it
    for k in range(2) {
        stake[k].points[0].y == base_rail.bb.top - 2 + 0 * k
        stake[k].bb.center_x == base_rail.center.x + (k - 0.5) * 50
    }

    # the request's numbers
    assert happy.size == 24 mm and age.size == 50 mm, "HAPPY 24 mm, 40 50 mm"
    assert top_rail.height == 4 mm and base_rail.height == 4 mm, "4 mm rails"
    assert base_rail.bb.left == star_l.bb.left and base_rail.bb.right == star_r.bb.right, "base rail from star to star"
    assert age.bb.left - star_l.bb.right == 6 mm and star_r.bb.left - age.bb.right == 6 mm, "stars 6 mm clear"
    assert base_rail.bb.bottom - stake[0].bb.bottom == 85 mm, "stakes 85 mm below the rail"
    assert stake[1].bb.center_x - stake[0].bb.center_x == 50 mm, "stakes 50 mm apart"
    assert topper.bb.width <= 140 mm, "no wider than 140 mm"
}
