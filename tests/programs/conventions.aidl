// Issue 14: conventions models guessed. A hexagon "flats parallel to the top edge" at
// rotation 0; ten holes 30 deg apart with step=; a slot 40 long end to end; text centered.
units mm

solid flange {
    disc = Circle(center=(0, 0), radius=60)
    hole hex {
        h = RegularPolygon(center=(0, 0), across_flats=30, sides=6)
    }
    hole bolt {
        b = Circle(center=(45, 0), radius=3)
    }
    holes = CircularPattern(bolt, 10, center=(0, 0), step=30 deg)
    hole slot {
        s = Slot(center=(0, -30), length=40, width=8)
    }
    drawing label {
        t = Text("A-1", (0, 30), size=6, valign="middle", rotation=0 deg)
    }
}
