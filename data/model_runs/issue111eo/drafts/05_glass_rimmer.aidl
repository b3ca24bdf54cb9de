# Request: a cocktail-party glass rimmer in 3 mm birch ply: three round wells side by side for
# salt, sugar and a lime-juice sponge, 100 mm across (a margarita glass's rim fits), on a
# 112 mm pitch. Four layers glued and stacked, each 350 x 140 mm with R12 corners: a solid
# base, two well layers (6 mm deep wells), and a lift-off lid with two finger slots 30 x 16 mm,
# 25 mm in from each end. (FIX: the slots are replaced by a finger notch R12 in the back edge
# of the well layers.) SALT / SUGAR / LIME engraved 6 mm high on the top well layer, 10 mm
# in front of each well; "HAPPY HOUR" in bold serif 20 mm, filled engraving, centred on the lid.

thickness 3 mm

W = 350 mm
Hgt = 140 mm
well_d = 100 mm
pitch = 112 mm
names = ["SALT", "SUGAR", "LIME"]

def board() -> solid {
    body = RoundedRectangle(center=(0, 0), width=W, height=Hgt, corner_radius=12)
}

def wells_layer() -> solid {
    body = RoundedRectangle(center=(0, 0), width=W, height=Hgt, corner_radius=12)
    hole well { c = Circle(center=(-pitch, 0), diameter=well_d) }
    wells = LinearPattern(well, 3, (pitch, 0))
    At(well.c.center, body.center, dx=-pitch)
    # FIX after the first valid program: the lid's finger slots, 25 mm in from its ends, lay
    # right over the end wells (they reach 13 mm from the ends): a finger went into the salt.
    # The slots are gone; instead a finger notch R12 in the back edge of both well layers,
    # centred, gets a finger under the lid (8 mm clear of the middle well)
    hole notch { c = Circle(center=(0, Hgt / 2), radius=12) }
    At(notch.c.center, body.top.midpoint)
}

assembly rimmer {
    base = board()
    lower = wells_layer()
    upper = wells_layer()
    lid = board()

    drawing labels {
        for i in range(3) {
            t = Text(names[i], position=(0, 0), size=6, anchor="middle", valign="top")
        }
    }
    for i in range(3) {
        At(labels.t[i].position, upper.wells[i].c.center, dy=-well_d / 2 - 10 mm)
    }
    CutInto(labels, upper)

    drawing title {
        t = Text("HAPPY HOUR", position=(0, 0), size=20, font="serif:Bold", valign="middle",
                 fill=true)
    }
    At(title.t.position, lid.body.center)
    CutInto(title, lid)

    # on the sheet: a column
    Below(lower, base, gap=6)
    AlignLeft(lower, base)
    Below(upper, lower, gap=6)
    AlignLeft(upper, lower)
    Below(lid, upper, gap=6)
    AlignLeft(lid, upper)

    # stacked in 3D
    Place(base, position=(0, 0, 0), face="up")
    Place(lower, position=(0, 0, 3 mm), face="up")
    Place(upper, position=(0, 0, 6 mm), face="up")
    Place(lid, position=(0, 0, 9 mm), face="up")

    # the request's numbers
    assert base.body.width == 350 mm and base.body.height == 140 mm
    assert len(upper.wells) == 3 and len(lower.wells) == 3
    assert upper.wells[0].c.diameter == 100 mm
    assert upper.wells[1].c.center.x - upper.wells[0].c.center.x == 112 mm
    assert upper.wells[2].c.center.x - upper.wells[1].c.center.x == 112 mm
    assert upper.wells[1].c.center.x == upper.body.center.x, "wells centred"
    assert labels.t[0].size == 6 mm
    assert upper.wells[0].c.bb.bottom - labels.t[0].position.y == 10 mm
    assert distance(labels, upper.wells[0]) >= 3 mm and distance(labels, upper.wells[1]) >= 3 mm
    assert labels.bb.bottom - upper.body.bb.bottom >= 3 mm, "labels on the board"
    assert upper.wells[1].c.bb.top + 8 mm == upper.notch.c.bb.bottom, "notch clear of the well"
    assert title.t.size == 20 mm
}
