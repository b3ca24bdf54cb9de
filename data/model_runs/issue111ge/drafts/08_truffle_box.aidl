# Request (gifts): a box of nine truffles for my sister Maya's birthday, 3 mm walnut ply.
# - A rounded box on living hinges (the stdlib flex_box), 120 x 120 x 45 mm outside, corners R20.
# - A loose insert that rests on the base's lip inside the wall: 113 x 113 mm, corners R16.5,
#   with nine 30 mm round pockets in a 3 x 3 grid at 36 mm pitch, centred (truffles about 25 mm
#   across and 25 mm tall).
# - On the lid: "MAYA" engraved filled in bold italic serif, 22 mm, in the centre; "HAPPY BIRTHDAY"
#   in 6 mm single-stroke letters over the top on a 38 mm radius round the centre; a row of five
#   filled 8 mm five-point stars 12 mm apart, 28 mm below the centre.

import "std/boxes.aidl"

thickness 3 mm

box_size = 120 mm
box_h = 45 mm
pocket_d = 30 mm
pitch = 36 mm
truffle = 25 mm

assembly gift {
    k = flex_box(length=120 mm, width=120 mm, height=45 mm, radius=20 mm, thickness=3 mm)

    solid insert {
        plate = RoundedRectangle(center=(0, 0), width=113, height=113, corner_radius=16.5)
        hole pocket {
            c = Circle(center=(-36, -36), diameter=30)
        }
        pockets = GridPattern(pocket, 3, 3, 36)
    }
    RightOf(insert, k, gap=5)
    AlignBottom(insert, k)
    # in 3D: on the base's lip (base 3 + lip 3 above the base's bottom face)
    Place(insert, on=k.base, position=(0, 0, 6))

    drawing deco {
        ring = Circle(center=(0, 0), radius=38, construction=true)
        top = Text("HAPPY BIRTHDAY", along=ring, size=6)
        name = Text("MAYA", position=(0, 0), size=22, font="serif:Bold Italic", valign="middle", fill=true)
        s = Star(center=(-24, -28), points=5, outer_radius=4, inner_radius=1.8, fill=true)
        stars = LinearPattern(s, 5, (12, 0))
    }
    Coincident(deco.ring.center, k.lid.bb.center)
    CutInto(deco, k.lid)

    # the request's numbers
    assert len(insert.pockets) == 9, "nine truffles"
    assert insert.pockets[1].c.center.x - insert.pockets[0].c.center.x == 36 mm, "36 pitch"
    assert insert.pocket.c.diameter == 30 mm and pocket_d - truffle >= 3 mm, "pockets 30, room round a 25 truffle"
    assert insert.plate.bb.width <= box_size - 2 * 3 mm - 0.5 mm, "insert fits inside the wall"
    assert pitch - pocket_d >= 5 mm, "wood between pockets"
    assert 3 mm + 3 mm + truffle <= box_h - 3 mm - 3 mm - 2 mm, "truffles clear of the lid's lip"
    assert len(deco.stars) == 5 and deco.stars[4].center.x - deco.stars[0].center.x == 48 mm, "five stars 12 apart"
    assert deco.stars[0].bb.width <= 8 mm, "stars 8 across"
    assert deco.ring.center.y - deco.stars[0].center.y == 28 mm, "stars 28 below the centre"
    assert deco.top.bb.top - deco.ring.center.y <= box_size / 2 - 20 mm + 5 mm, "arc text on the lid"
    assert deco.name.bb.top < deco.ring.center.y + 38 mm - 3 mm, "MAYA under the arc"
}
