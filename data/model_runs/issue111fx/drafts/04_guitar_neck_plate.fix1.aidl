# Request: a custom neck plate for my bolt-on T-style guitar build, cut by a fibre-laser
# service in 3 mm aluminium, plus a 1 mm plastic cushion (gasket) under it with the same
# outline and holes. Standard 4-bolt size: 2.5 x 2 in (63.5 x 50.8 mm), the four neck-screw
# holes 4.5 mm on the standard pattern 1.75 x 1.25 in (3/8 in in from each edge), countersunk
# 8.5 mm in the plate (not in the gasket). The neck-pocket end's corners R6, the other end
# rounded R15 to follow the body's heel contour. Engraved on the plate: a border line 3 mm
# in from the edge, "J. ROWE" in serif bold, filled, 6 mm tall, and under it "No. 0147" and
# "2026", all between the two rows of screws.
# FIX after the first valid program: at the R15 end the 3 mm border (R12, concentric) touched
# the 8.5 mm countersinks' rims (no message: my assert measured the 4.5 mm holes, not the
# heads). The border moves to 2 mm in (R13 there), 1 mm clear of the heads.

units mm
import "std/shapes.aidl"

plate_l = 2.5 in
plate_w = 2 in

def neck_outline() -> solid {
    body = RoundedRectangle(center=(0, 0), width=plate_l, height=plate_w,
                            corner_radii=[6, 15, 15, 6])
    hole screw { c = Circle(center=(0, 0), diameter=4.5) }
    screws = CornerPattern(screw, body, inset=0.375 in)
}

assembly neck_plate {
    solid plate {
        thickness 3 mm
        o = neck_outline()
        Countersink(o.screws, diameter=8.5)
        drawing border {
            b = RoundedRectangle(center=(0, 0), width=63.5 - 4, height=50.8 - 4,
                                 corner_radii=[4, 13, 13, 4])
        }
        drawing maker {
            name = Text("J. ROWE", position=(0, 3), size=6, font="serif:Bold", fill=true)
            serial = Text("No. 0147", position=(0, -4), size=3.5, font="serif")
            year = Text("2026", position=(0, -9), size=3, font="serif")
        }
    }

    solid gasket {
        thickness 1 mm
        o = neck_outline()
    }

    RightOf(gasket, plate, gap=5)
    AlignCenterY(gasket, plate)
    # on the guitar's back: the gasket on the body, the plate on the gasket
    Place(gasket, position=(0, 0, 0))
    Place(plate, position=(0, 0, 1))

    # the request's numbers
    assert plate.o.body.width == 63.5 mm and plate.o.body.height == 50.8 mm, "2.5 x 2 in plate"
    assert gasket.o.body.width == 63.5 mm and gasket.o.body.height == 50.8 mm, "same gasket"
    assert len(plate.o.screws) == 4, "four neck screws"
    assert plate.o.screw.c.diameter == 4.5 mm, "4.5 mm holes"
    assert plate.o.screws[1].c.center.x - plate.o.screws[0].c.center.x == 1.75 in,
        "1.75 in along the plate"
    assert plate.o.screws[3].c.center.y - plate.o.screws[0].c.center.y == 1.25 in,
        "1.25 in across it"
    assert plate.o.screws[0].c.center.x - plate.o.body.bb.left == 0.375 in, "3/8 in from the end"
    # the text stays between the rows of countersinks and inside the border
    assert plate.maker.bb.top <= plate.o.screws[3].c.center.y - 8.5 mm / 2 - 1 mm,
        "text below the upper countersinks"
    assert plate.maker.bb.bottom >= plate.o.screws[0].c.center.y + 8.5 mm / 2 + 1 mm,
        "text above the lower countersinks"
    assert plate.maker.bb.width <= 63.5 mm - 2 * 2 mm - 4 mm, "text inside the border"
    assert plate.maker.name.size == 6 mm, "6 mm name"
    assert distance(plate.border, plate.o.screws) >= 8.5 mm / 2 - 4.5 mm / 2 + 1 mm,
        "border 1 mm clear of the countersinks' rims"
}
