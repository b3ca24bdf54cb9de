# Request (signs): "A door sign for our home recording studio, 3 mm birch ply, 320 mm
# wide, 105 mm tall at the sides with an arched top rising to 135 mm in the middle,
# bottom corners rounded 8 mm. QUIET (30 mm) over PLEASE (22 mm) cut right through as
# bold stencil letters (lit from behind by the red ON AIR lamp), both centred 20 mm
# right of the middle; RECORDING IN PROGRESS engraved (7 mm) along the bottom, centred,
# its middle 15 mm above the bottom edge; a muted-speaker icon (speaker filled, a cross
# beside it) engraved at the left; two 5 mm holes for the hanging chain 40 mm in from
# the sides, 5 mm above the shoulders of the arch."

thickness 3 mm

solid sign {
    bottom = Line((-160, -60), (160, -60))
    right = Line((160, -60), (160, 45))
    top = Arc(start=(160, 45), through=(0, 75), end=(-160, 45))
    left = Line((-160, 45), (-160, -60))
    Fillet([bottom, right], 8)
    Fillet([bottom, left], 8)

    hole words {
        quiet = Text("QUIET", position=(20, 22), size=30, font="sans:Bold", stencil=true,
                     valign="middle")
        please = Text("PLEASE", position=(20, -15), size=22, font="sans:Bold", stencil=true,
                      valign="middle")
    }
    hole chain {
        l = Circle(center=(-120, 50), diameter=5)
        r = Circle(center=(120, 50), diameter=5)
    }
    drawing line2 {
        t = Text("RECORDING IN PROGRESS", position=(0, -45), size=7, valign="middle")
    }
    drawing icon {
        speaker = Polygon([(-135, -3), (-125, -3), (-113, -13), (-113, 23), (-125, 13), (-135, 13)],
                          fill=true)
        x1 = Line((-106, -2), (-94, 12))
        x2 = Line((-106, 12), (-94, -2))
    }

    assert bottom.length == 320 mm, "320 wide"
    assert right.length == 105 mm, "105 at the sides"
    assert top.through.y - bottom.start.y == 135 mm, "135 in the middle"
    assert words.quiet.size == 30 mm and words.please.size == 22 mm, "letter sizes"
    assert words.quiet.position.x == 20 mm and words.please.position.x == 20 mm, "words 20 right of the middle"
    assert line2.t.position.y - bottom.start.y == 15 mm, "bottom line 15 up"
    assert chain.l.center.x - left.start.x == 40 mm, "chain holes 40 in"
    assert chain.l.center.y - left.start.y == 5 mm, "chain holes 5 above the shoulder"
    assert distance(words, icon) >= 3 mm, "icon clear of the words"
}
