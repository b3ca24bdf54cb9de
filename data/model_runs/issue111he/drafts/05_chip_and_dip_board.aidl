# Request (parties): a chips-and-dip serving board for a party, two layers of 6 mm plywood
# glued together. The outline is a rounded paddle 410 mm long: a 240 mm round end and a
# 140 mm round end, smoothly joined. The top layer has two holes that hold the dip pots
# from sliding: 97 mm for the guacamole bowl (95 mm base) and 72 mm for the salsa (70 mm
# base); the bottom layer is whole under them. Both layers have a 60 x 24 mm handle slot in
# the narrow end, 35 mm from its tip. Engraved: CHIPS in filled bold letters 22 mm tall on
# the open area, and GUAC and SALSA curving round the top of their holes, 7 mm letters.

thickness 6 mm

def layer(top=true) -> solid {
    big = Circle(center=(-90, 0), radius=120)
    small = Circle(center=(130, 0), radius=70)
    body = Hull(big, small)
    hole handle { s = Slot(center=(165, 0), length=60, width=24, rotation=90) }
    if top {
        hole guac { c = Circle(center=(-120, 30), diameter=97) }
        hole salsa { c = Circle(center=(-60, -70), diameter=72) }
        drawing words {
            chips = Text("CHIPS", position=(60, 0), size=22, font="sans:Bold", valign="middle",
                         fill=true)
            guac_rim = Circle(center=(-120, 30), radius=48.5 + 3, construction=true)
            guac_label = Text("GUAC", along=guac_rim, size=7)
            salsa_rim = Circle(center=(-60, -70), radius=36 + 3, construction=true)
            salsa_label = Text("SALSA", along=salsa_rim, size=7)
        }
    }
}

assembly chip_and_dip {
    top_layer = layer(top=true)
    bottom_layer = layer(top=false)

    assert top_layer.body.bb.width == 410 mm, "410 mm long"
    assert top_layer.guac.c.diameter == 97 mm and top_layer.salsa.c.diameter == 72 mm,
        "pot holes 97 and 72"
    assert top_layer.small.center.x + top_layer.small.radius - top_layer.handle.s.center.x
        == 35 mm, "handle 35 mm from the tip"
    assert distance(top_layer.guac, top_layer.salsa) >= 10 mm, "a bridge between the pots"
    assert distance(top_layer.words.chips, top_layer.handle) >= 10 mm, "CHIPS clear of the handle"
    assert distance(top_layer.words.guac_label, top_layer.salsa) >= 3 mm, "labels clear"

    Below(bottom_layer, top_layer, gap=10)
    AlignLeft(bottom_layer, top_layer)
}
