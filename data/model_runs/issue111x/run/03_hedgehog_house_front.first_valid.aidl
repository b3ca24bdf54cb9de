# Garden: front panel of a hedgehog house, 6 mm exterior plywood. A gabled panel 300 mm
# wide, walls 200 mm tall, ridge 260 mm above the bottom. An arched entrance 130 mm wide
# and 130 mm tall (straight sides, a semicircular top of R65), centred, its sill 10 mm above
# the bottom edge. Five 10 mm vent holes at 25 mm pitch in the gable, centred, 215 mm up.
# Four 4 mm screw holes countersunk 8 mm, 12 mm in from the corners of the 300 x 200 wall.
# "HEDGEHOG HOUSE" engraved 12 mm tall, centred between the arch's top and the vents.

thickness 6 mm

solid front {
    panel = Polygon([(-150, 0), (150, 0), (150, 200), (0, 260), (-150, 200)])
    wall = Rectangle(center=(0, 100), width=300, height=200, construction=true)

    hole door {
        sill = Line((-65, 10), (65, 10))
        right = Line((65, 10), (65, 75))
        arch = Arc(center=(0, 75), start=(65, 75), end=(-65, 75))
        left = Line((-65, 75), (-65, 10))
    }
    AlignCenterX(door, panel)
    door.bb.bottom == panel.bb.bottom + 10 mm

    hole vent {
        c = Circle(center=(-50, 215), diameter=10)
    }
    vents = LinearPattern(vent, 5, (25, 0))

    hole screw {
        c = Circle(center=(-138, 12), diameter=4)
    }
    screws = CornerPattern(screw, wall, inset=12)
    Countersink(screw, diameter=8)

    drawing label {
        t = Text("HEDGEHOG HOUSE", (0, 175), size=12, valign="middle")
    }
    AlignCenterX(label, panel)
    label.bb.center_y == (door.bb.top + vent.bb.bottom) / 2
}

assert front.bb.width == 300 mm and front.bb.height == 260 mm, "300 wide, ridge 260 up"
assert front.door.bb.width == 130 mm and front.door.bb.height == 130 mm, "entrance 130 x 130"
assert front.door.arch.radius == 65 mm, "arch R65"
assert front.door.bb.bottom - front.bb.bottom == 10 mm, "sill 10 mm up"
assert front.door.bb.center_x == front.panel.bb.center_x, "entrance centred"
assert len(front.vents) == 5, "five vents"
assert front.vents[1].c.center.x - front.vents[0].c.center.x == 25 mm, "vent pitch 25"
assert front.vents[2].c.center.x == front.panel.bb.center_x, "vents centred"
assert front.vent.c.center.y - front.bb.bottom == 215 mm, "vents 215 up"
assert len(front.screws) == 4, "four screws"
assert front.screws[0].c.center.x - front.bb.left == 12 mm, "screws 12 in"
assert front.screws[0].c.center.y - front.bb.bottom == 12 mm, "screws 12 up"
