# Request: cloakroom (coat-check) tags for a party, 3 mm birch ply, 20 numbered pairs.
# Each pair: a hanger tag 45 x 80 with R6 corners and a 14 mm hole centred 12 below its top
# edge (it drops over the coat hanger's hook), its number engraved filled in bold sans 20 tall
# in the middle and CLOAKROOM engraved (single stroke, 4 tall) near its bottom; and a guest tag
# 35 x 55 with R5 corners and a 5 mm hole 7 below its top edge (for a key ring), its number in
# bold sans 14 tall and GUEST (single stroke, 3.5 tall) under it. Numbers 1 to 20, laid out for
# one 600 x 400 sheet: the hanger tags in two rows of ten on a 50 x 90 grid, the guest tags in
# two rows of ten under them on a 50 x 65 grid.

units mm
thickness 3 mm
kerf 0.15 mm

PAIRS = 20

def hanger_tag(n=1) -> solid {
    body = RoundedRectangle(center=(0, 0), width=45, height=80, corner_radius=6)
    hole eye {
        c = Circle(center=(0, 40 - 12), diameter=14)
    }
    drawing number {
        t = Text(str(n), position=(0, -4), size=20, font="sans:Bold", valign="middle", fill=true)
    }
    drawing word {
        t = Text("CLOAKROOM", position=(0, -32), size=4, valign="middle")
    }
}

def guest_tag(n=1) -> solid {
    body = RoundedRectangle(center=(0, 0), width=35, height=55, corner_radius=5)
    hole eye {
        c = Circle(center=(0, 27.5 - 7), diameter=5)
    }
    drawing number {
        t = Text(str(n), position=(0, -1), size=14, font="sans:Bold", valign="middle", fill=true)
    }
    drawing word {
        t = Text("GUEST", position=(0, -18), size=3.5, valign="middle")
    }
}

assembly cloakroom {
    for i in range(PAIRS) {
        h = hanger_tag(n=i + 1)
        g = guest_tag(n=i + 1)
        h.body.center == (-225 + (i % 10) * 50, 140 - (i // 10) * 90)
        g.body.center == (-225 + (i % 10) * 50, -57.5 - (i // 10) * 65)
    }

    # the request's numbers
    assert len(h) == 20 and len(g) == 20, "20 pairs"
    assert h[0].body.width == 45 mm and h[0].body.height == 80 mm, "hanger tag 45 x 80"
    assert g[0].body.width == 35 mm and g[0].body.height == 55 mm, "guest tag 35 x 55"
    assert h[0].eye.c.diameter == 14 mm, "14 mm hanger hole"
    assert h[0].body.bb.top - h[0].eye.c.center.y == 12 mm, "hanger hole 12 below the top"
    assert g[0].eye.c.diameter == 5 mm, "5 mm key-ring hole"
    assert g[0].body.bb.top - g[0].eye.c.center.y == 7 mm, "key-ring hole 7 below the top"
    assert h[19].number.t.text == "20" and g[19].number.t.text == "20", "numbered to 20"
    assert h[1].body.center.x - h[0].body.center.x == 50 mm, "50 grid"
    assert h[0].body.center.y - h[10].body.center.y == 90 mm, "90 grid"
    assert g[0].body.center.y - g[10].body.center.y == 65 mm, "65 grid"
    assert distance(h[0].eye, h[0].number) >= 2 mm, "the hole clear of the number"
    assert distance(g[0].eye, g[0].number) >= 2 mm, "the hole clear of the number"
    assert distance(h[10], g[0]) >= 3 mm, "the rows do not touch"
}
