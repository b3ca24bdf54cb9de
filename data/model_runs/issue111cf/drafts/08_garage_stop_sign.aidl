# Request: a "STOP" sign hung from the garage ceiling on two cords, so the car stops at the
# right spot. Two 3 mm acrylic octagons glued together, flats at top and bottom, corners
# rounded 6 mm: a white back 200 mm across the flats and a red front 188 mm across (a 6 mm
# white border shows round it). "STOP" cut out of the red front as a bold stencil (counters
# held by bridges), 50 mm tall and at most 150 mm wide, the white showing through, and
# "PARK HERE" engraved under it (10 mm). Two 4 mm cord holes through both layers, 100 mm
# apart, 20 mm below the red front's top flat.

thickness 3 mm

AF_back = 200 mm
AF_front = 188 mm

assembly stop_sign {
    solid back {
        body = RegularPolygon(center=(0, 0), across_flats=AF_back, sides=8, rotation=22.5 deg)
        hole cords {
            l = Circle(center=(-50, AF_front / 2 - 20), diameter=4)
            r = Circle(center=(50, AF_front / 2 - 20), diameter=4)
        }
        Fillet(body, 6)
    }

    solid front {
        body = RegularPolygon(center=(0, 0), across_flats=AF_front, sides=8,
                              rotation=22.5 deg)
        hole cords {
            l = Circle(center=(-50, AF_front / 2 - 20), diameter=4)
            r = Circle(center=(50, AF_front / 2 - 20), diameter=4)
        }
        hole letters {
            word = Text("STOP", (0, 8), size=50, font="sans:Bold", stencil=true,
                        valign="middle", max_width=150)
        }
        drawing note {
            t = Text("PARK HERE", (0, -50), size=10, valign="middle")
        }
        Fillet(body, 6)
    }

    # flat on the sheet
    RightOf(front, back, gap=10)
    AlignCenterY(front, back)

    # in 3D: the red front glued on the white back
    Place(back, position=(0, 0, 0))
    Place(front, position=(0, 0, 3))

    assert back.body.bb.height == 200 mm, "white back 200 across the flats"
    assert (back.body.bb.height - front.body.bb.height) / 2 == 6 mm, "6 mm white border"
    assert front.letters.word.bb.width <= 150 mm, "STOP at most 150 wide"
    assert front.cords.r.center.x - front.cords.l.center.x == 100 mm, "cords 100 apart"
    assert front.body.bb.top - front.cords.l.center.y == 20 mm, "cords 20 below the top"
}
