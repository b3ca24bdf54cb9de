# Request: a shrimp cave for a planted aquarium, stacked from five layers of 4 mm clear
# cast acrylic glued with acrylic cement. The outline is a pebble about 110 x 70 mm (a
# smooth closed curve). The bottom three layers are walls: each has an oval chamber
# 64 x 32 mm in the middle (2 mm behind the centre) and a doorway 22 mm wide from the
# chamber out through the front edge, so the cave is 12 mm high inside with one entrance.
# The fourth layer is the roof, the outline shrunk by 3 mm; the fifth, the cap, shrunk by
# 7 mm. Three 5 mm holes through roof and cap over the chamber (20 mm apart, on its
# long axis) let water flow through. Every wall around the chamber at least 10 mm.

units mm
thickness 4 mm

pebble = [(-55, -5), (-48, -28), (-20, -35), (15, -33), (45, -25), (55, 0), (42, 28),
          (10, 35), (-25, 33), (-50, 20)]

def wall_layer() -> solid {
    body = Spline(pebble, closed=true)
    hole chamber {
        e = Ellipse(center=(0, 2), rx=32, ry=16)
        door = Rectangle(center=(0, -30), width=22, height=36, overrun=true)
    }
}

def roof_layer(shrink=3 mm) -> solid {
    edge = Spline(pebble, closed=true, construction=true)
    body = Inset(edge, shrink)
    hole vents {
        for i in range(3) {
            c = Circle(center=((i - 1) * 20, 2), diameter=5)
        }
    }
}

assembly cave {
    for i in range(3) {
        wall = wall_layer()
        Place(wall, position=(0, 0, i * 4), face="up")
    }
    roof = roof_layer(shrink=3 mm)
    cap = roof_layer(shrink=7 mm)
    Place(roof, position=(0, 0, 12), face="up")
    Place(cap, position=(0, 0, 16), face="up")

    # flat: in a row
    RightOf(wall[1], wall[0], gap=4)
    AlignCenterY(wall[1], wall[0])
    RightOf(wall[2], wall[1], gap=4)
    AlignCenterY(wall[2], wall[0])
    RightOf(roof, wall[2], gap=4)
    AlignCenterY(roof, wall[0])
    RightOf(cap, roof, gap=4)
    AlignCenterY(cap, wall[0])

    # the request's numbers
    assert len(wall) == 3, "three wall layers"
    assert abs(wall[0].body.bb.width - 110 mm) <= 6 mm and abs(wall[0].body.bb.height - 70 mm) <= 6 mm, "about 110 x 70"
    assert wall[0].chamber.e.bb.width == 64 mm and wall[0].chamber.e.bb.height == 32 mm, "chamber 64 x 32"
    assert wall[0].chamber.door.width == 22 mm, "doorway 22"
    assert wall[0].chamber.door.bb.bottom < wall[0].body.bb.bottom, "doorway opens through the front"
    assert wall[0].body.bb.top - wall[0].chamber.e.bb.top >= 10 mm, "back wall 10"
    assert wall[0].chamber.e.bb.left - wall[0].body.bb.left >= 10 mm, "left wall 10"
    assert wall[0].body.bb.right - wall[0].chamber.e.bb.right >= 10 mm, "right wall 10"
    assert abs(roof.body.bb.width - (wall[0].body.bb.width - 6 mm)) < 0.01 mm, "roof shrunk 3"
    assert abs(cap.body.bb.width - (wall[0].body.bb.width - 14 mm)) < 0.01 mm, "cap shrunk 7"
    assert roof.vents.c[1].center.x - roof.vents.c[0].center.x == 20 mm, "vents 20 apart"
    assert cap.body.bb.left < cap.vents.c[0].bb.left - 5 mm, "vents inside the cap"
}
