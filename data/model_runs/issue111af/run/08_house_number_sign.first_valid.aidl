# Request (signs): a layered house-number sign. 6 mm ply, 4 parts:
# - a back plate 320 x 160 mm, R12 corners, with two countersunk screw holes (4.5 mm, 9 mm
#   countersink) 140 mm either side of the middle, "ELM ROAD" engraved filled in serif capitals
#   18 mm high centred 55 mm below the middle, and the outline of the numerals engraved as a
#   glue guide where they go;
# - the numerals "42" cut out as separate letters in bold sans, 90 mm cap height, their middle
#   15 mm above the plate's middle (glued on the guide);
# - two round wall spacers 20 mm across with a 4.5 mm hole, to stand the sign off the wall.

units mm
thickness 6 mm
import "std/shapes.aidl"

number = "42"
num_size = 90 mm
num_y = 15 mm
street = "ELM ROAD"

assembly house_sign {
    solid plate {
        body = RoundedRectangle(center=(0, 0), width=320, height=160, corner_radius=12)
        hole screws {
            left = Circle(center=(-140, 0), diameter=4.5)
            right = Circle(center=(140, 0), diameter=4.5)
        }
        Countersink(screws, diameter=9 mm)
        drawing guide {
            g = Text(number, position=(0, num_y), size=num_size, font="sans:Bold", valign="middle")
        }
        drawing street_name {
            s = Text(street, position=(0, -55), size=18, font="serif", valign="middle", fill=true)
        }
        Fixed(body)
    }

    solid numerals {
        n = Text(number, position=(0, num_y), size=num_size, font="sans:Bold", valign="middle")
    }

    s1 = washer(outer=20 mm, inner=4.5 mm)
    s2 = washer(outer=20 mm, inner=4.5 mm)

    # laid out for cutting
    Below(numerals, plate, gap=10)
    AlignLeft(numerals, plate)
    RightOf(s1, numerals, gap=10)
    AlignTop(s1, numerals)
    RightOf(s2, s1, gap=10)
    AlignTop(s2, s1)

    assert plate.body.width == 320 mm and plate.body.height == 160 mm, "plate 320 x 160"
    assert plate.screws.right.center.x - plate.body.center.x == 140 mm, "screws 140 from the middle"
    assert plate.screws.left.diameter == 4.5 mm, "4.5 mm screw holes"
    assert numerals.n.size == 90 mm, "90 mm numerals"
    assert plate.guide.g.position.y - plate.body.center.y == 15 mm, "numerals 15 above the middle"
    assert plate.street_name.s.position.y - plate.body.center.y == -55 mm, "street 55 below the middle"
    assert plate.street_name.s.size == 18 mm, "street 18 high"
    assert s1.ring.diameter == 20 mm and s1.bore.b.diameter == 4.5 mm, "spacers 20 / 4.5"
}
