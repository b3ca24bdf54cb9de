# Tea-light tray top: a 200 x 70 mm plate with R8 corners and three 39.5 mm
# holes for tea lights (38 mm cups + clearance), 60 mm apart center to center,
# centered; a 3 mm hole 6 mm in from each corner for the legs' screws,
# countersunk 6 mm.
thickness 4 mm

param pitch = 60 mm, min = 45 mm, max = 65 mm

solid tray {
    plate = RoundedRectangle(center=(0, 0), width=200, height=70, corner_radius=8)
    hole cup {
        c = Circle(center=(-pitch, 0), diameter=39.5)
    }
    cups = LinearPattern(cup, 3, (pitch, 0))
    AlignCenterY(cup, plate)
    cup.c.center.x == plate.center.x - pitch

    hole screw {
        c = Circle(center=(-94, -29), diameter=3)
    }
    screws = CornerPattern(screw, plate, inset=6 mm)
    Countersink(screws, diameter=6 mm)
}

assert tray.plate.bb.width == 200 mm and tray.plate.bb.height == 70 mm, "200 x 70 plate"
assert len(tray.cups) == 3, "three tea lights"
assert tray.cups[1].c.center.x - tray.cups[0].c.center.x == 60 mm, "60 mm apart"
assert tray.cups[2].c.center.x - tray.plate.center.x == 60 mm, "centered row"
assert tray.cup.c.diameter == 39.5 mm, "39.5 mm holes"
assert tray.screw.c.center.x - tray.plate.bb.left == 6 mm, "screw 6 mm in"
assert tray.screw.c.center.y - tray.plate.bb.bottom == 6 mm, "screw 6 mm in"
assert len(tray.screws) == 4, "a screw at each corner"
