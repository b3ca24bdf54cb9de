# Request: a sewing-table pincushion caddy from 3 mm birch plywood, two layers glued.
# Both layers are 180 x 110 mm with R8 corners. The top layer has a 64 mm round well at
# the left (its centre 52 mm left of the middle and 12 mm above it) into which a stuffed
# fabric cushion is glued, the base closing the well's bottom; three 21.5 mm bobbin
# pockets in a row on the right (centres at x = 10, 38 and 66 mm from the middle, 18 mm
# below it); "SEW HAPPY" engraved filled in 8 mm bold capitals along the front, 44 mm
# below the middle. Behind the pockets stand three thread-spool pegs, each 8 mm wide,
# 60 mm tall above the top layer with a round top, on a 4 mm tenon 6 mm long through
# 4 x 3 mm mortises in both layers, centred 25 mm above the middle over each pocket.
# Five parts.

units mm
t = 3 mm
thickness t
kerf 0.1 mm

peg_x = [10 mm, 38 mm, 66 mm]
peg_y = 25 mm

def peg() -> solid {
    shaft = RoundedRectangle(bottom_left=(-4, 2 * t), width=8, height=60, corner_radii=[4, 4, 0, 0])
    tenon = Rectangle(bottom_left=(-2, 0), width=4, height=2 * t)
}

assembly caddy {
    solid base {
        plate = RoundedRectangle(center=(0, 0), width=180, height=110, corner_radius=8)
        for i in range(3) {
            hole m { r = Rectangle(center=(peg_x[i], peg_y), width=4, height=t) }
        }
        Fixed(plate)
    }
    solid top {
        plate = RoundedRectangle(center=(0, 0), width=180, height=110, corner_radius=8)
        hole well {
            c = Circle(center=(-52, 12), diameter=64)
        }
        for i in range(3) {
            hole pocket { c = Circle(center=(peg_x[i], -18), diameter=21.5) }
            hole m { r = Rectangle(center=(peg_x[i], peg_y), width=4, height=t) }
        }
        drawing motto {
            words = Text("SEW HAPPY", position=(0, -44), size=8, font="sans:Bold", valign="middle",
                         fill=true)
        }
        Fixed(plate)

        assert plate.width == 180 mm and plate.height == 110 mm, "layers 180 x 110"
        assert well.c.diameter == 64 mm, "64 mm well"
        assert well.c.center.x - plate.center.x == -52 mm and well.c.center.y - plate.center.y == 12 mm,
            "well 52 mm left and 12 mm up"
        assert len(pocket) == 3 and pocket[0].c.diameter == 21.5 mm, "three 21.5 mm bobbin pockets"
        assert pocket[2].c.center.x - plate.center.x == 66 mm and pocket[2].c.center.y - plate.center.y == -18 mm,
            "last pocket at (66, -18)"
        assert distance(well, pocket) >= 4 mm, "pockets clear of the well"
        assert distance(motto, pocket) >= 3 mm and distance(motto, well) >= 3 mm, "motto clear of the openings"
        assert motto.bb.bottom - plate.bb.bottom >= 4 mm, "motto on the plate"
        assert distance(pocket, m) >= 1.5 mm, "a wall between each pocket and its mortise"
    }
    RightOf(top, base, gap=6)
    AlignCenterY(top, base)
    for i in range(3) {
        pegs = peg()
        Place(pegs, position=(peg_x[i], peg_y + t / 2, 0), face="front", up="up")
    }
    Below(pegs[0], base, gap=6)
    AlignLeft(pegs[0], base)
    RightOf(pegs[1], pegs[0], gap=6)
    AlignBottom(pegs[1], pegs[0])
    RightOf(pegs[2], pegs[1], gap=6)
    AlignBottom(pegs[2], pegs[1])

    Place(base, position=(0, 0, 0))
    Place(top, position=(0, 0, t))

    assert len(pegs) == 3, "three spool pegs"
    assert pegs[0].shaft.width == 8 mm and pegs[0].shaft.height == 60 mm, "pegs 8 wide, 60 tall"
    assert pegs[0].tenon.width == 4 mm and pegs[0].tenon.height == 6 mm, "4 mm tenon 6 mm long"
    assert base.m[1].r.center.x == top.m[1].r.center.x and base.m[1].r.center.y == top.m[1].r.center.y,
        "mortises line up in both layers"
}
