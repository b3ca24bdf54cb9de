# Request: a keyhole escutcheon with a swinging drop cover for the mortice lock of an old
# pine door, cut from 3 mm walnut ply. Back plate: a stadium 36 mm wide and 90 mm tall
# (fully rounded ends). Keyhole: a 9 mm round opening whose centre is 12 mm below the plate's
# centre, with a tapered bit slot under it 14 mm long (from the circle's centre down),
# 5 mm wide at the top and 7 mm at the bottom. Two 4 mm screw holes on the centre line:
# 33 mm above the plate's centre (the cover's pivot screw, plain in the plate) and 36 mm
# below it (countersunk for an 8 mm head). A line engraved 3 mm inside the plate's edge.
# Cover: a drop hung on the top screw: a round top of R7 round the 4 mm pivot hole
# (countersunk 8 mm, the screw's head sits on the cover) blending into a round foot of R13
# whose centre is 4.75 mm below the keyhole circle's centre, so the whole keyhole is
# covered; it must clear the bottom screw's head by at least 1 mm.
# Laid out side by side 10 mm apart to cut; assembled: the cover on the plate's front.

thickness 3 mm

param plate_w = 36 mm, min = 30 mm, max = 50 mm
param plate_h = 90 mm, min = 80 mm, max = 120 mm

assembly escutcheon {
    solid plate {
        body = Slot(center=(0, 0), length=plate_h, width=plate_w, rotation=90)
        hole key {
            c = Circle(center=(0, -12), diameter=9)
            bit = Trapezoid(center=(0, -19), bottom_width=7, top_width=5, height=14)
        }
        hole pivot_screw { c = Circle(center=(0, 33), diameter=4) }
        hole low_screw { c = Circle(center=(0, -36), diameter=4) }
        Countersink(low_screw, diameter=8)
        drawing border {
            b = Slot(center=(0, 0), length=plate_h - 6, width=plate_w - 6, rotation=90)
        }
    }

    solid cover {
        top = Circle(center=(0, 33), radius=7, construction=true)
        foot = Circle(center=(0, -16.75), radius=13, construction=true)
        body = Hull(top, foot)
        hole pivot { c = Circle(center=(0, 33), diameter=4) }
        Countersink(pivot, diameter=8)
    }

    RightOf(cover, plate, gap=10)
    AlignTop(cover, plate)

    Place(plate, position=(0, 0, 0), face="front")
    Place(cover, position=(0, -3, 0), face="front")

    # the request's numbers
    assert plate.body.bb.width == 36 mm, "plate 36 wide"
    assert plate.body.bb.height == 90 mm, "plate 90 tall"
    assert plate.key.c.diameter == 9 mm, "9 mm keyhole"
    assert plate.body.center.y - plate.key.c.center.y == 12 mm, "keyhole 12 below centre"
    assert plate.key.bit.top.midpoint.y == plate.key.c.center.y, "bit slot starts at the circle centre"
    assert plate.key.c.center.y - plate.key.bit.bottom.midpoint.y == 14 mm, "bit slot 14 long"
    assert plate.pivot_screw.c.center.y - plate.body.center.y == 33 mm, "pivot screw 33 above"
    assert plate.body.center.y - plate.low_screw.c.center.y == 36 mm, "low screw 36 below"
    # the cover: pivots on the top screw, covers the keyhole, clears the low screw's head
    assert cover.pivot.c.center.y == plate.pivot_screw.c.center.y, "cover hangs on the pivot screw"
    assert plate.key.c.center.y - cover.foot.center.y == 4.75 mm, "foot 4.75 below keyhole centre"
    assert cover.body.bb.bottom <= plate.key.bb.bottom - 1 mm, "keyhole covered at the bottom"
    assert cover.body.bb.bottom >= plate.low_screw.c.center.y + 4 mm + 1 mm, "clears the low screw head"
    assert cover.body.bb.width <= plate.body.bb.width - 6 mm, "cover inside the border"
}
