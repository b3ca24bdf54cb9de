# Wall tool cleat: a 240 x 60 mm plate with 6 mm chamfered corners; three
# 4.5 mm screw holes countersunk to 9 mm on the horizontal center line, 20 mm
# in from each end and one in the middle; along the top edge four 25 mm wide,
# 15 mm deep U-notches (rounded bottoms) for tool handles, at 48 mm pitch,
# centered on the plate.
thickness 6 mm

param pitch = 48 mm, min = 35 mm, max = 55 mm

solid cleat {
    plate = Rectangle(center=(0, 0), width=240, height=60)
    Chamfer(plate, 6)
    hole screw {
        c = Circle(center=(-100, 0), diameter=4.5)
    }
    screws = LinearPattern(screw, 3, (100, 0))
    Countersink(screws, diameter=9 mm)
    hole notch {
        u = Slot(start=(-1.5 * pitch, 30 - 15 + 12.5), end=(-1.5 * pitch, 40), width=25)
    }
    notches = LinearPattern(notch, 4, (pitch, 0))
}

assert cleat.plate.bb.width == 240 mm and cleat.plate.bb.height == 60 mm, "240 x 60"
assert len(cleat.screws) == 3, "three screws"
assert cleat.screw.c.center.x - cleat.plate.bb.left == 20 mm, "20 mm in from the end"
assert cleat.screws[1].c.center.x == cleat.plate.center.x, "one in the middle"
assert len(cleat.notches) == 4, "four notches"
assert cleat.plate.bb.top - cleat.notch.u.bb.bottom == 15 mm, "15 mm deep"
assert cleat.notch.u.width == 25 mm, "25 mm wide"
assert cleat.notches[1].u.start.x - cleat.notches[0].u.start.x == 48 mm, "48 mm pitch"
assert cleat.notches[0].u.start.x + cleat.notches[3].u.start.x == 2 * cleat.plate.center.x, "centered"
