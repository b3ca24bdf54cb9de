# Jar lid insert with a grip: an 86 mm disc whose rim has 30 round grip notches,
# each 4 mm across, centred on the rim; an engraved 60 mm ring as decoration and
# the word "JAM" (10 mm tall) in the middle.
param d = 86 mm, min = 50 mm, max = 120 mm
param notches = 30, min = 12, max = 48

solid lid {
    disc = Circle(center=(0, 0), diameter=d)

    hole notch {
        n = Circle(center=(d / 2, 0), diameter=4)
    }
    Coincident(notch.n.center, polar(disc.center, d / 2, 0 deg))
    CircularPattern(notch, notches, disc.center)

    drawing deco {
        ring = Circle(center=(0, 0), diameter=60)
        word = Text("JAM", position=(0, 0), size=10, valign="middle")
    }
    CenterInside(deco, disc)
}
