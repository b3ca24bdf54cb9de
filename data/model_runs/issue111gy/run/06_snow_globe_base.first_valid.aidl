# Request: a stacked base for a 100 mm DIY snow globe, five glued layers of 6 mm ply (30 mm
# tall). Bottom: a 130 mm disc with a 20 mm thumb hole to push the LED tealight out. Three
# rings above it make an 18 mm deep pocket, 42 mm across, for a 38 mm LED tealight: two rings
# 130 mm across and one stepped in to 124 mm. Top: a 116 mm ring with a 62 mm seat the globe's
# foot sits in (the light shines up into the globe). On the top ring: "MERRY CHRISTMAS"
# engraved along its rim over the top and "2026" under, 7 mm tall (bold sans, filled), with a
# small filled five-pointed star at each side.

units mm
thickness 6 mm
kerf 0.15 mm

pocket = 42 mm
tealight = 38 mm

def layer(od=130 mm, bore=42 mm) -> solid {
    disc = Circle(center=(0, 0), diameter=od)
    hole bore_hole {
        c = Circle(center=(0, 0), diameter=bore)
    }
}

assembly snow_globe_base {
    bottom = layer(od=130 mm, bore=20 mm)
    ring1 = layer(od=130 mm, bore=pocket)
    ring2 = layer(od=130 mm, bore=pocket)
    ring3 = layer(od=124 mm, bore=pocket)
    top = layer(od=116 mm, bore=62 mm)

    RightOf(ring1, bottom, gap=8)
    AlignBottom(ring1, bottom)
    RightOf(ring2, ring1, gap=8)
    AlignBottom(ring2, ring1)
    Below(ring3, bottom, gap=8)
    AlignLeft(ring3, bottom)
    RightOf(top, ring3, gap=8)
    AlignTop(top, ring3)

    drawing greeting {
        rim = Circle(center=(0, 0), radius=41, construction=true)
        words = Text("MERRY CHRISTMAS", along=rim, size=7, font="sans:Bold", fill=true)
        year = Text("2026", along=rim, size=7, font="sans:Bold", fill=true, flip=true)
        star_r = Star(center=(44.5, 0), points=5, outer_radius=4.5, inner_radius=1.9, fill=true)
        star_l = Star(center=(-44.5, 0), points=5, outer_radius=4.5, inner_radius=1.9, fill=true)
    }
    Concentric(greeting.rim, top.disc)
    CutInto(greeting, top)

    assert bottom.disc.diameter == 130 mm and bottom.bore_hole.c.diameter == 20 mm, "bottom disc"
    assert ring3.disc.diameter == 124 mm and top.disc.diameter == 116 mm, "stepped rings"
    assert top.bore_hole.c.diameter == 62 mm, "62 mm seat"
    assert 3 * 6 mm == 18 mm and pocket - tealight >= 2 mm, "pocket fits the tealight"
    assert top.bore_hole.c.diameter > tealight, "the tealight goes in from the top"
    assert distance(greeting, top.bore_hole) >= 2 mm, "engraving clear of the seat"
    assert top.disc.radius - (41 mm + 7 mm) >= 3 mm, "engraving clear of the rim"
}
