# Request (signs): a "FIRE DOOR / KEEP SHUT" mandatory sign, two layers of acrylic.
# Back: white 3 mm acrylic disc 200 mm across. Top: blue 2 mm acrylic disc 196 mm across
# (a 2 mm white rim shows round it) with "FIRE DOOR" and "KEEP SHUT" cut through it as bold
# stencil letters (the white shows through), each line at most 150 mm wide and 22 mm tall,
# their middles 20 mm above and below the centre. Two screws fix both layers to the door,
# 82 mm above and below the centre: 4.5 mm holes, countersunk (9 mm heads) in the top layer.

units mm

assembly fire_door_sign {
    solid back {
        thickness 3 mm
        disc = Circle(center=(0, 0), diameter=200)
        for s in [1, -1] {
            hole screw { c = Circle(center=(0, s * 82), diameter=4.5) }
        }
    }
    solid top {
        thickness 2 mm
        disc = Circle(center=(0, 0), diameter=196)
        for s in [1, -1] {
            hole screw { c = Circle(center=(0, s * 82), diameter=4.5) }
        }
        Countersink(screw, diameter=9)
        hole words {
            l1 = Text("FIRE DOOR", position=(0, 20), size=22, font="sans:Bold", valign="middle",
                      stencil=true, max_width=150)
            l2 = Text("KEEP SHUT", position=(0, -20), size=22, font="sans:Bold", valign="middle",
                      stencil=true, max_width=150)
        }
    }

    # flat on the sheet: side by side
    RightOf(top, back, gap=10)
    AlignCenterY(top, back)

    # assembled: the top layer on the back one
    Place(back, position=(0, 0, 0))
    Place(top, position=(0, 0, 3))

    # the request's numbers
    assert back.disc.diameter == 200 mm and top.disc.diameter == 196 mm, "200 and 196"
    assert top.words.l1.bb.width <= 150 mm and top.words.l2.bb.width <= 150 mm, "lines <= 150"
    assert top.words.l1.position.y - top.disc.center.y == 20 mm, "FIRE DOOR 20 above"
    assert top.disc.center.y - top.words.l2.position.y == 20 mm, "KEEP SHUT 20 below"
    assert top.screw[0].c.center.y - top.disc.center.y == 82 mm, "screw 82 above"
    assert top.disc.center.y - top.screw[1].c.center.y == 82 mm, "screw 82 below"
    assert back.screw[0].c.center.y - back.disc.center.y == 82 mm, "back screw 82 above"
}
