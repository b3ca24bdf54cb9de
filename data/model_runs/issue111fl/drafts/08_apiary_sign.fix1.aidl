# Request: a warning sign for the gate of my apiary, two layers of 3 mm acrylic glued
# together. The back: yellow, a hexagon 300 across the flats (flats top and bottom). The face:
# black, the same hexagon 8 mm smaller all round (284 across the flats), with the design cut
# through it so the yellow shows: a honeycomb band of pointy-top hexagons 16 across the flats
# with 3 mm walls, 7 in a lower row at y = 95.5 and 6 in the row above, staggered; "BEES" in
# bold letters 50 tall (baseline 28, centred); "PLEASE KEEP BACK" in bold, 16 tall, baseline
# -10, at most 250 wide; and a bee about 100 wide centred at (0, -80): an oval body 68 x 34 with a
# pointed sting, a round head R11, two wings 20 x 30 tilted 20 deg leaving 4 mm of black
# above the body, two antennae 3 wide, and three black stripes 6 wide across the body. Two
# 5.5 mm holes through both layers at (0, 131) and (0, -128), countersunk 10 mm in the face.

units mm
thickness 3 mm

assembly sign {
    solid back {
        hexa = RegularPolygon(center=(0, 0), across_flats=300 mm, sides=6)
        for y in [131 mm, -128 mm] {
            hole screw { c = Circle(center=(0, y), diameter=5.5 mm) }
        }
    }

    solid face {
        solid panel {
            hexa = RegularPolygon(center=(0, 0), across_flats=284 mm, sides=6)
            for r in range(2) {
                for c in range(7 - r) {
                    hole cell { h = RegularPolygon(center=(-57 mm + c * 19 mm + r * 9.5 mm, 95.5 mm + r * 16.45 mm),
                                                   across_flats=16 mm, sides=6, rotation=30 deg) }
                }
            }
            hole word { t = Text("BEES", position=(0, 28 mm), size=50 mm, font="sans:Bold", stencil=true) }
            hole warning { t = Text("PLEASE KEEP BACK", position=(0, -10 mm), size=16 mm, font="sans:Bold",
                                    stencil=true, max_width=250 mm) }
            hole bee {
                body = Ellipse(center=(0, -80 mm), rx=34 mm, ry=17 mm)
                sting = Polygon([(30 mm, -84 mm), (30 mm, -76 mm), (46 mm, -80 mm)])
                head = Circle(center=(-40 mm, -80 mm), radius=11 mm)
                # FIX after the first valid program: wings 18 apart merged into one heart-shaped
                # opening; now 28 apart, two wings
                wing_l = Ellipse(center=(-14 mm, -44 mm), rx=10 mm, ry=15 mm, rotation=20 deg)
                wing_r = Ellipse(center=(14 mm, -44 mm), rx=10 mm, ry=15 mm, rotation=-20 deg)
                ant_l = Slot(start=(-44 mm, -71 mm), end=(-52 mm, -58 mm), width=3 mm)
                ant_r = Slot(start=(-38 mm, -70 mm), end=(-40 mm, -56 mm), width=3 mm)
            }
            for y in [131 mm, -128 mm] {
                hole screw { c = Circle(center=(0, y), diameter=5.5 mm) }
            }
            Countersink(screw, diameter=10 mm)
        }
        # the bee's stripes: black bars left across the body's opening
        solid stripes {
            for x in [-8 mm, 6 mm, 20 mm] {
                bar = Rectangle(center=(x, -80.5 mm), width=6 mm, height=39 mm)
            }
        }
        AllowOverlap(stripes, panel.bee)
    }

    # flat, for cutting
    RightOf(face, back, gap=10 mm)
    AlignCenterY(face, back)

    # assembled: the face glued on the back
    Place(back, position=(0, 0, 0), face="front", up="up")
    Place(face, position=(0, -3 mm, 0), face="front", up="up")

    assert back.hexa.across_flats == 300 mm, "back 300 across the flats"
    assert back.hexa.across_flats - face.panel.hexa.across_flats == 16 mm, "face 8 smaller all round"
    assert len(face.panel.cell[0]) == 7 and len(face.panel.cell[1]) == 6, "7 and 6 cells"
    assert face.panel.cell[1][0].h.center.y - face.panel.cell[0][0].h.center.y == 16.45 mm, "rows staggered"
    assert face.panel.bee.bb.width <= 100 mm, "bee about 100 wide"
    assert face.panel.bee.body.bb.top + 4 mm <= face.panel.bee.wing_l.bb.bottom + 0.5 mm, "4 mm of black over the body"
    assert distance(face.panel.screw[0].c, face.panel.cell) >= 3 mm, "top screw clear of the honeycomb"
    assert distance(face.panel.warning, face.panel.bee) >= 3 mm, "words clear of the bee"
    assert distance(face.panel.bee.wing_l, face.panel.bee.wing_r) >= 3 mm, "two wings, apart"
    assert distance(face.panel.word, face.panel.warning) >= 3 mm, "BEES clear of the warning"
}
