# Request: a workshop "wear eye protection" mandatory sign (after ISO 7010 M004), three
# layers of 3 mm acrylic glued together. Back: white, 240 x 330 mm, R10 corners, four
# countersunk M4 holes 14 mm in from the corners, "EYE PROTECTION" and "MUST BE WORN" engraved
# filled in bold letters 24 mm tall (at most 196 mm wide) under the disc. Middle: a blue disc
# 200 mm across, its centre 45 mm above the plate's centre. Front: the white pictogram, a
# head (70 x 88 mm oval) on a neck and shoulders clipped to a circle 12 mm inside the disc's
# edge, with goggles cut out of the face so the blue shows through: two 26 x 17 mm lenses
# with an 8 mm nose bridge and the strap running out to both sides of the head.

import "std/fasteners.aidl"

thickness 3 mm

disc_c = (0, 45)

assembly sign {
    solid back {
        plate = RoundedRectangle(center=(0, 0), width=240, height=330, corner_radius=10)
        screw = clearance_hole(size=4)
        corners = CornerPattern(screw, plate, inset=14)
        Countersink(corners, diameter=8.5)
        drawing words {
            line1 = Text("EYE PROTECTION", position=(0, -88), size=24, font="sans:Bold",
                         valign="middle", max_width=196, fill=true)
            line2 = Text("MUST BE WORN", position=(0, -128), size=24, font="sans:Bold",
                         valign="middle", max_width=196, fill=true)
        }
        Fixed(plate)
    }

    solid disc {
        d = Circle(center=disc_c, diameter=200)
    }

    solid pictogram {
        head = Ellipse(center=(0, 45 + 22), rx=35, ry=44)
        neck = Rectangle(center=(0, 45 - 25), width=28, height=22)
        block = RoundedRectangle(center=(0, 45 - 70), width=150, height=62, corner_radius=28)
        rim = Circle(center=disc_c, radius=100 - 12)
        shoulders = Intersect(block, rim)
        hole goggles {
            left = RoundedRectangle(center=(-17, 45 + 26), width=26, height=17, corner_radius=7)
            right = RoundedRectangle(center=(17, 45 + 26), width=26, height=17, corner_radius=7)
            strap_l = Rectangle(center=(-36, 45 + 26), width=12, height=6)
            strap_r = Rectangle(center=(36, 45 + 26), width=12, height=6)
        }
    }

    # flat on the sheet
    RightOf(disc, back, gap=10)
    AlignTop(disc, back)
    Below(pictogram, disc, gap=10)
    AlignCenterX(pictogram, disc)

    # assembled: stacked and glued
    Place(back, position=(0, 0, 0))
    Place(disc, position=(0, 0, 3 mm))
    Place(pictogram, position=(0, 0, 6 mm))

    assert back.plate.width == 240 mm and back.plate.height == 330 mm
    assert len(back.corners) == 4
    assert back.corners[0].c.center.x - back.plate.bb.left == 14 mm
    assert back.corners[0].c.center.y - back.plate.bb.bottom == 14 mm
    assert disc.d.diameter == 200 mm
    assert disc.d.center.y - back.plate.center.y == 45 mm
    assert pictogram.head.rx * 2 == 70 mm and pictogram.head.ry * 2 == 88 mm
    assert pictogram.goggles.right.center.x - pictogram.goggles.left.center.x - 26 mm == 8 mm,
        "8 mm nose bridge"
    assert back.words.line1.size <= 24 mm
}
