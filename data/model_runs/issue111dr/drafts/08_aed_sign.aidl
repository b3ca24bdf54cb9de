# Request (signs): a defibrillator sign for the sports club wall, layered 3 mm stock.
# - Back plate (green acrylic) 200 wide x 240 tall, R10 corners, four 4.5 mm holes for
#   4 mm countersunk screws (9 mm heads) 12 mm in from each corner; "AED" (22 mm) and
#   "DEFIBRILLATOR" (14 mm) filled-engraved under the heart.
# - A heart (white acrylic) 112 mm wide, 110 mm tall: the hull of a 60 mm circle and the
#   heart's point each side (lobes' centres 52 mm apart, 25 mm above its middle, the point
#   55 mm below it), with a lightning bolt cut through it so the green shows; glued on with
#   its middle 10 mm left of the plate's centre line, 25 mm above the plate's middle.
# - A white cross (plus sign) 36 x 36 mm, arms 12 mm wide, corners R1.5, glued at the top
#   right, its centre 65 mm right of and 85 mm above the plate's middle, clear of the heart
#   and the screw heads.

units mm
thickness 3 mm

sign_w = 200 mm
sign_h = 240 mm
heart_x = -10 mm
heart_y = 25 mm       # above the plate's middle
cross_x = 65 mm
cross_y = 85 mm

assembly aed {
    solid back {
        plate = RoundedRectangle(center=(0, 0), width=sign_w, height=sign_h, corner_radius=10)
        hole screw { c = Circle(center=(-sign_w / 2 + 12, -sign_h / 2 + 12), diameter=4.5) }
        screws = CornerPattern(screw, plate, inset=12)
        Countersink(screw, diameter=9)
        drawing words {
            aed_word = Text("AED", position=(0, -62), size=22, valign="middle",
                            font="sans:Bold", fill=true)
            defib = Text("DEFIBRILLATOR", position=(0, -95), size=14, valign="middle",
                         font="sans:Bold", fill=true)
        }
    }

    solid heart {
        left_lobe = Hull(Circle(center=(-26, 25), diameter=60), Point(0, -55))
        right_lobe = Hull(Circle(center=(26, 25), diameter=60), Point(0, -55))
        hole bolt {
            zig = Polygon([(4, 38), (-16, 2), (-2, 2), (-10, -32), (16, 8), (2, 8), (12, 38)])
        }
        Rigid(self)
    }

    solid cross {
        bar_h = Rectangle(center=(0, 0), width=36, height=12)
        bar_v = Rectangle(center=(0, 0), width=12, height=36)
        Fillet(1.5)
        Rigid(self)
    }

    # flat on the sheet
    RightOf(heart, back, gap=8)
    AlignTop(heart, back)
    Below(cross, heart, gap=8)
    AlignLeft(cross, heart)

    # on the wall: the back's face to the front, the heart and the cross glued on it
    Place(back, position=(0, 0, 0), face="front", up="up")
    Place(heart, position=(heart_x, -3 mm, heart_y), face="front", up="up")
    Place(cross, position=(cross_x, -3 mm, cross_y), face="front", up="up")

    # the request's numbers
    assert back.plate.width == 200 mm and back.plate.height == 240 mm, "200 x 240"
    assert len(back.screws) == 4, "four screws"
    assert back.screw.c.center.x - back.plate.bb.left == 12 mm, "12 in from the corner"
    assert heart.bb.width == 112 mm and heart.bb.height == 110 mm, "heart 112 x 110"
    assert cross.bb.width == 36 mm and cross.bb.height == 36 mm, "cross 36"
    # clear of the heart: the cross's near corner to the right lobe's circle
    assert sqrt((cross_x - 18 mm - (heart_x + 26 mm)) ** 2 +
                (cross_y - 18 mm - (heart_y + 25 mm)) ** 2) > 30 mm + 3 mm,
        "the cross 3 mm clear of the heart"
    # clear of the top right screw head (9 mm): its centre to the arms' outer corners
    assert distance((88 mm, 108 mm), (cross_x + 6 mm, cross_y + 18 mm)) >= 6.5 mm and
        distance((88 mm, 108 mm), (cross_x + 18 mm, cross_y + 6 mm)) >= 6.5 mm,
        "clear of the screw head"
    assert back.screws[2].c.center.x == 88 mm and back.screws[2].c.center.y == 108 mm,
        "the top right screw where the clearance above measured it"
    # the heart's point above the AED word
    assert heart_y - 55 mm > -62 mm + 11 mm + 3 mm, "the heart clear of AED"
}
