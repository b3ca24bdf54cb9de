# Hexagonal coaster: a regular hexagon 100 mm across the flats with its corners
# rounded to 5 mm; an engraved border hexagon 8 mm inside the edge, and an engraved
# 3 mm-tall "TEA" at the centre.
param af = 100 mm, min = 80 mm, max = 130 mm

solid coaster {
    hex = RegularPolygon(center=(0, 0), across_flats=af, sides=6)
    Fillet(5)
    drawing deco {
        border = RegularPolygon(center=(0, 0), across_flats=af - 16, sides=6)
        word = Text("TEA", position=(0, 0), size=3, valign="middle")
    }
    Concentric(deco.border, hex)
    Concentric(deco.word, hex)
}
