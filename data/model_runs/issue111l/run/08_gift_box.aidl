# Gifts: a small gift box with a lift-off lid (lid_box) 100 x 100 x 60 mm outside, 3 mm
# plywood, 10 mm fingers; on the lid "FOR YOU" engraved filled in sans Bold 12 mm tall,
# centred across, the letters' middle 12 mm below the lid's centre; above it a five-pointed
# star cut through the lid (outer radius 12 mm, inner 5 mm), centred across, its centre
# 15 mm above the lid's centre.

import "std/boxes.aidl"

thickness 3 mm

assembly gift {
    box = lid_box(length=100 mm, width=100 mm, height=60 mm, thickness=3 mm, finger=10 mm)

    drawing greeting {
        word = Text("FOR YOU", (0, 0), size=12, font="sans:Bold", fill=true, valign="middle")
    }
    AlignCenterX(greeting, box.lid)
    greeting.word.position.y == box.lid.bb.center_y - 12
    CutInto(greeting, box.lid)

    hole star {
        s = Star(center=(0, 0), points=5, outer_radius=12, inner_radius=5)
    }
    star.s.center.x == box.lid.bb.center_x
    star.s.center.y == box.lid.bb.center_y + 15
    CutInto(star, box.lid)

    assert box.lid.bb.width == 100 mm and box.lid.bb.height == 100 mm, "lid 100 x 100"
    assert greeting.word.size == 12 mm, "12 mm letters"
    assert box.lid.bb.center_y - greeting.word.position.y == 12 mm, "12 below the centre"
    assert abs(greeting.bb.center_x - box.lid.bb.center_x) < 0.5 mm, "centred across"
    assert star.s.outer_radius == 12 mm and star.s.inner_radius == 5 mm, "star 12 / 5"
    assert star.s.center.y - box.lid.bb.center_y == 15 mm, "star 15 above the centre"
    assert star.bb.bottom > greeting.bb.top, "star clear of the letters"
    assert greeting.bb.width < box.lid.bb.width - 20 mm, "letters fit on the lid"
}
