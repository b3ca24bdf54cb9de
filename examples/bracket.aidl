# A flat mounting bracket: a plate with two tapered ears (one made, one mirrored
# about the plate's center line), a row of bolt holes made by a linear pattern,
# a ring of vent holes made by a circular pattern, and filleted corners.
# Try: --set bolts=5  --set pitch=16  --set fillet=1

param bolts = 4
param pitch = 20 mm
param fillet = 3 mm

def vent(d=4 mm) -> hole {
    v = Circle(center=(0, 0), diameter=d)
}

solid bracket {
    plate = Rectangle(center=(0, 0), width=(bolts + 0.5) * pitch, height=40)
    axis = Line((0, -30), (0, 30), construction=true)
    Vertical(axis)
    Midpoint(plate.center, axis)

    solid ear {
        tab = Trapezoid(center=(60, 0), bottom_width=30, top_width=14, height=20,
                        rotation=-90 deg)
        hole eye {
            e = Circle(center=(60, 0), radius=3)
        }
        CenterInside(eye, tab)
    }
    LeftOf(plate, ear, gap=-1)
    AlignCenterY(ear, plate)
    other_ear = Mirrored(ear, about=axis)

    hole bolt {
        c = Circle(center=(0, 12), radius=3)
    }
    holes = LinearPattern(bolt, bolts, (pitch, 0))
    HorizontalDistance(plate.left.midpoint, holes[0].c.center, 0.75 * pitch)

    first = vent()
    CircularPattern(first, 8, plate.center)
    VerticalDistance(first.v.center, plate.center, 9)
    AlignCenterX(first, plate)

    Fillet(fillet)
}
