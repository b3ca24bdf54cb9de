# Request: a nursery name hoop, a new-baby gift, in 3 mm birch ply to hang on the wall. A ring
# 250 mm across the outside, the band 12 mm wide; a hanging tab at the top, 24 mm across with
# an 8 mm hole, its joins to the ring rounded R3. Across the hoop the name "Florence" cut out
# as the material itself in bold italic serif, about 45 mm capitals but no wider than 200 mm,
# standing on a rail 10 mm tall whose ends run into the ring's band; the letters sink 1 mm into
# the rail so they join it. The birth date "12 . 05 . 2026" engraved 5 mm high on the rail.

thickness 3 mm

outer_d = 250 mm
band = 12 mm
r_in = outer_d / 2 - band
r_mid = outer_d / 2 - band / 2
rail_top = -20 mm
rail_h = 10 mm
rail_w = 2 * sqrt(r_mid * r_mid - (rail_top - rail_h) * (rail_top - rail_h))

solid hoop {
    # the ring as its own child: its inner hole must not cut the rail and the letters
    solid ring {
        outer = Circle(center=(0, 0), diameter=outer_d)
        tab = Circle(center=(0, outer_d / 2 + 4 mm), diameter=24)
        Fillet([outer, tab], 3)
        hole inside { edge = Circle(center=(0, 0), radius=r_in) }
        hole hang { c = Circle(center=(0, outer_d / 2 + 4 mm), diameter=8) }
        Concentric(hang.c, tab)
        Concentric(inside.edge, outer)
    }
    edge = ring.inside.edge

    rail = Rectangle(center=(0, rail_top - rail_h / 2), width=rail_w, height=rail_h)
    name = Text("Florence", position=(0, rail_top - 1 mm), size=45, font="serif:Bold Italic",
                max_width=200)

    drawing date {
        d = Text("12 . 05 . 2026", position=(0, rail_top - rail_h / 2 - 1 mm), size=5,
                 valign="middle")
    }

    # the request's numbers
    assert ring.outer.diameter == 250 mm, "250 mm across"
    assert edge.radius == 113 mm, "band 12 mm"
    assert ring.tab.diameter == 24 mm and ring.hang.c.diameter == 8 mm
    assert name.bb.width <= 200 mm
    assert rail.height == 10 mm
    assert rail.bb.left <= -edge.radius - 2 mm and rail.bb.right >= edge.radius + 2 mm,
        "rail ends run into the band"
    assert distance(rail.bottom_left, edge.center) <= outer_d / 2 - 2 mm, "rail ends inside the band"
    assert rail.bb.top - name.position.y == 1 mm, "letters sink 1 mm into the rail"
    assert date.d.size == 5 mm
    assert distance(date, name) >= 1 mm, "date clear of the letters"
    assert date.bb.bottom >= rail.bb.bottom + 1 mm
}
