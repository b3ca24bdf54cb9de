# Bathroom: a hair-dryer holder in 6 mm plywood, two parts glued together.
# Back plate 120 wide x 160 tall, corners R10, screwed to the wall by two 4.5 mm
# holes countersunk 9 mm (90 deg), on the centre line, 20 mm below the top edge and
# 25 mm above the bottom edge. Two mortises 20.2 x 6.2 mm, centres 35 mm left and
# right of the centre line, their centres 40 mm below the top edge.
# Shelf 120 wide x 90 deep, its two front corners R10 (back corners square); two
# tabs 20 x 6 mm on its back edge, centres 35 mm left and right of its centre line,
# that glue into the mortises. A 55 mm hole for the nozzle, its centre 50 mm in from
# the back edge, with a 20 mm wide cable slot from the hole to the front edge.

units mm
thickness 6 mm

assembly dryer_holder {
    solid back {
        body = RoundedRectangle(center=(0, 0), width=120, height=160, corner_radius=10)
        hole mortise {
            m1 = Rectangle(center=(-35, 40), width=20.2, height=6.2)
            m2 = Rectangle(center=(35, 40), width=20.2, height=6.2)
        }
        hole screws {
            top = Circle(center=(0, 60), diameter=4.5)
            low = Circle(center=(0, -55), diameter=4.5)
        }
        Countersink(screws, diameter=9 mm)
    }

    solid shelf {
        body = RoundedRectangle(center=(0, 0), width=120, height=90,
                                corner_radii=[0, 0, 10, 10])
        tab1 = Rectangle(center=(-35, 48), width=20, height=6)
        tab2 = Rectangle(center=(35, 48), width=20, height=6)
        hole nozzle {
            c = Circle(center=(0, -5), diameter=55)
            cable = Rectangle(center=(0, -26), width=20, height=42)
        }
    }
    Rigid(shelf)
    RightOf(shelf, back, gap=10)
    AlignTop(shelf, back)

    # the request's numbers
    assert back.body.width == 120 mm and back.body.height == 160 mm, "back 120 x 160"
    assert back.body.bb.top - back.screws.top.center.y == 20 mm, "top screw 20 below the top"
    assert back.screws.low.center.y - back.body.bb.bottom == 25 mm, "low screw 25 above the bottom"
    assert back.screws.top.center.x == back.body.center.x, "screws on the centre line"
    assert back.screws.top.diameter == 4.5 mm, "4.5 mm screw holes"
    assert back.body.bb.top - back.mortise.m1.center.y == 40 mm, "mortises 40 below the top"
    assert back.mortise.m2.center.x - back.body.center.x == 35 mm, "mortise 35 right of centre"
    assert back.body.center.x - back.mortise.m1.center.x == 35 mm, "mortise 35 left of centre"
    assert back.mortise.m1.width == 20.2 mm and back.mortise.m1.height == 6.2 mm, "mortise 20.2 x 6.2"
    assert shelf.body.width == 120 mm and shelf.body.height == 90 mm, "shelf 120 x 90"
    assert shelf.tab1.width == 20 mm and shelf.tab1.height == 6 mm, "tabs 20 x 6"
    assert shelf.tab1.bottom.midpoint.y == shelf.body.bb.top, "tabs on the back edge"
    assert shelf.tab2.center.x - shelf.body.center.x == 35 mm, "tab 35 right of centre"
    assert shelf.tab2.center.x - shelf.tab1.center.x == back.mortise.m2.center.x - back.mortise.m1.center.x, "tabs match the mortises"
    assert shelf.nozzle.c.diameter == 55 mm, "55 mm nozzle hole"
    assert shelf.body.bb.top - shelf.nozzle.c.center.y == 50 mm, "hole centre 50 from the back edge"
    assert shelf.nozzle.cable.width == 20 mm, "20 mm cable slot"
    assert shelf.nozzle.cable.bb.bottom < shelf.body.bb.bottom, "the cable slot opens the front edge"
}
