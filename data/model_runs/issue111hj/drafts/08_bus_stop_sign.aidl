# Request (signs): a stop sign for our village's community minibus, 3 mm white acrylic,
# engraved filled, strapped to a 76 mm lamp post with two stainless band clamps.
# - plate 220 x 320 mm (portrait), 12 mm corner radii.
# - at the top a roundel: a ring 110 mm across, 8 mm wide, centred 75 mm above the
#   plate's middle; inside it a bus seen from the front: body 50 x 56 mm with 6 mm
#   rounded corners, a windscreen 40 x 22 mm (left unengraved) 6 mm below its top, two
#   8 mm headlamps (unengraved) 8 mm above its bottom, 12 mm in from its sides, two
#   wheels 10 x 8 mm under it 16 mm either side of its middle, two mirrors 4 x 10 mm
#   beside the windscreen.
# - "BUS STOP" in bold capitals, 30 mm, centred 10 mm below the middle, at most 190 wide.
# - three route tiles, 44 x 30 mm outlines with 5 mm radii, 55 mm apart, centred 80 mm
#   below the middle: "7", "12", "X3" in 18 mm bold; under them "Mon-Sat every 20 min",
#   7 mm single stroke, centred 118 mm below the middle.
# - for the clamps: four vertical slots 3 x 16 mm, two at the top and two at the bottom,
#   their centres 145 mm above and below the middle and 38 mm either side of it.
thickness 3 mm

ROUTES = ["7", "12", "X3"]

solid sign {
    plate = RoundedRectangle(center=(0, 0), width=220, height=320, corner_radius=12)

    drawing roundel {
        inner = Circle(center=(0, 75), radius=55 - 8, construction=true)
        ring = Shell(inner, 8, fill=true)
    }

    drawing bus {
        body = RoundedRectangle(center=(0, 75), width=50, height=56, corner_radius=6, fill=true)
        wheel_l = Rectangle(center=(-16, 75 - 28 - 4), width=10, height=8, fill=true)
        wheel_r = Rectangle(center=(16, 75 - 28 - 4), width=10, height=8, fill=true)
        mirror_l = Rectangle(center=(-25 - 3, 75 + 28 - 6 - 11), width=4, height=10, fill=true)
        mirror_r = Rectangle(center=(25 + 3, 75 + 28 - 6 - 11), width=4, height=10, fill=true)
        hole windscreen {
            w = Rectangle(center=(0, 75 + 28 - 6 - 11), width=40, height=22)
        }
        hole lamps {
            l = Circle(center=(-25 + 12, 75 - 28 + 8), diameter=8)
            r = Circle(center=(25 - 12, 75 - 28 + 8), diameter=8)
        }
    }

    drawing title {
        t = Text("BUS STOP", position=(0, -10), size=30, font="sans:Bold", valign="middle",
                 max_width=190, fill=true)
    }

    drawing routes {
        for i in range(3) {
            tile = RoundedRectangle(center=(-55 + i * 55, -80), width=44, height=30,
                                    corner_radius=5)
            num = Text(ROUTES[i], position=(-55 + i * 55, -80), size=18, font="sans:Bold",
                       valign="middle", fill=true)
        }
        times = Text("Mon-Sat every 20 min", position=(0, -118), size=7, valign="middle")
    }

    hole clamps {
        tl = Rectangle(center=(-38, 145), width=3, height=16)
        tr = Rectangle(center=(38, 145), width=3, height=16)
        bl = Rectangle(center=(-38, -145), width=3, height=16)
        br = Rectangle(center=(38, -145), width=3, height=16)
    }

    assert plate.width == 220 mm and plate.height == 320 mm, "plate 220 x 320"
    assert roundel.inner.radius + 8 mm == 110 mm / 2, "ring 110 across, 8 wide"
    assert roundel.inner.center.y - plate.center.y == 75 mm, "roundel 75 above the middle"
    assert bus.body.bb.top - bus.windscreen.w.bb.top == 6 mm, "windscreen 6 below the top"
    assert bus.lamps.l.center.y - bus.body.bb.bottom == 8 mm, "lamps 8 above the bottom"
    assert bus.body.bb.right - bus.lamps.r.center.x == 12 mm, "lamps 12 in from the sides"
    assert distance(bus, roundel.ring) >= 3 mm, "the bus clear of the ring"
    assert title.t.bb.width <= 190 mm, "BUS STOP at most 190 wide"
    assert len(routes.tile) == 3, "three routes"
    assert routes.tile[1].center.x - routes.tile[0].center.x == 55 mm, "tiles 55 apart"
    assert routes.tile[0].center.y - plate.center.y == -80 mm, "tiles 80 below the middle"
    for i in range(3) {
        assert routes.num[i].bb.width <= routes.tile[i].width - 8 mm, "number fits its tile"
    }
    assert clamps.tr.center.x - clamps.tl.center.x == 76 mm, "slots 76 apart: the post"
    assert distance(clamps, roundel) >= 3 mm, "slots clear of the roundel"
    assert distance(clamps, routes) >= 3 mm, "slots clear of the route line"
    assert distance(title, roundel) >= 5 mm, "title clear of the roundel"
    assert distance(title, routes) >= 5 mm, "title clear of the tiles"
}
