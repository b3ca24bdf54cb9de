# Request (signs): a level sign for the makerspace's stair landing, two layers of 3 mm
# acrylic, 180 wide x 240 tall with 12 mm corners, on four 4.5 mm countersunk screws
# (9 mm heads) 10 mm in from each corner through both layers. The white front layer has the
# level number "2", 110 mm tall in bold sans, and "LEVEL" 20 mm tall above it, both cut
# through so the blue back layer shows in them. Under the number, engraved filled: a stair
# pictogram of four steps, 60 wide x 45 tall, climbing to the right, and beside it two
# 10 mm lines "↑ 3 – 4" and "↓ 0 – 1  EXIT". The blue back layer: the same outline and
# screw holes, not sunk.

thickness 3 mm

assembly sign {
    solid front {
        plate = RoundedRectangle(center=(0, 0), width=180, height=240, corner_radius=12)
        hole h { c = Circle(center=(0, 0), diameter=4.5) }
        screws = CornerPattern(h, plate, inset=10)
        Countersink(screws, diameter=9)
        hole word {
            t = Text("LEVEL", position=(0, 85), size=20, font="sans:Bold")
        }
        hole number {
            t = Text("2", position=(0, -35), size=110, font="sans:Bold")
        }
        drawing guide {
            stairs = Polygon([(-80, -95), (-20, -95), (-20, -50), (-35, -50), (-35, -61.25),
                              (-50, -61.25), (-50, -72.5), (-65, -72.5), (-65, -83.75),
                              (-80, -83.75)], fill=true)
            up = Text("↑ 3 – 4", position=(-10, -62), size=10, anchor="start",
                      font="sans:Bold", fill=true)
            down = Text("↓ 0 – 1  EXIT", position=(-10, -90), size=10, anchor="start",
                        font="sans:Bold", fill=true)
        }
        Fixed(plate)
    }

    solid back {
        plate = RoundedRectangle(center=(0, 0), width=180, height=240, corner_radius=12)
        hole h { c = Circle(center=(0, 0), diameter=4.5) }
        screws = CornerPattern(h, plate, inset=10)
        Fixed(plate)
    }

    RightOf(back, front, gap=10)
    AlignTop(back, front)
    Place(back, position=(0, 0, 0))
    Place(front, position=(0, 0, 3))

    # the request's numbers
    assert front.plate.bb.width == 180 mm and front.plate.bb.height == 240 mm, "plate 180 x 240"
    assert front.screws[0].c.center.x - front.plate.bb.left == 10 mm and
        front.screws[0].c.center.y - front.plate.bb.bottom == 10 mm, "screws 10 in from the corner"
    assert front.number.t.size == 110 mm and front.word.t.size == 20 mm, "2 is 110, LEVEL 20"
    assert front.word.bb.bottom - front.number.bb.top >= 4 mm, "LEVEL clear of the 2"
    assert front.plate.bb.top - front.word.bb.top >= 10 mm, "LEVEL inside the top"
    assert front.number.bb.bottom - front.guide.bb.top >= 4 mm, "pictogram clear of the 2"
    assert front.guide.stairs.bb.width == 60 mm and front.guide.stairs.bb.height == 45 mm,
        "stairs 60 x 45"
    assert front.guide.up.bb.left - front.guide.stairs.bb.right >= 5 mm, "lines beside the stairs"
    assert front.guide.down.bb.right <= front.plate.bb.right - 8 mm, "EXIT inside the plate"
    assert distance(front.guide.down, front.screws[1]) >= 5 mm, "EXIT clear of the screw"
    assert front.guide.stairs.bb.bottom - front.plate.bb.bottom >= 20 mm, "stairs above the bottom"
}
