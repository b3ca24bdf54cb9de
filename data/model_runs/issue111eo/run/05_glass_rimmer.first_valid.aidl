# Request: a cocktail-party glass rimmer in 3 mm birch ply: three round wells side by side for
# salt, sugar and a lime-juice sponge, 100 mm across (a margarita glass's rim fits), on a
# 112 mm pitch. Four layers glued and stacked, each 350 x 140 mm with R12 corners: a solid
# base, two well layers (6 mm deep wells), and a lift-off lid with two finger slots 30 x 16 mm,
# 25 mm in from each end. SALT / SUGAR / LIME engraved 6 mm high on the top well layer, 10 mm
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

    hole grip { s = Slot(center=(0, 0), length=30, width=16, rotation=90) }
    grips = LinearPattern(grip, 2, (W - 2 * 25 mm, 0))
    grip.s.center.x == lid.bb.left + 25 mm
    AlignCenterY(grip, lid)
    CutInto(grip, lid)

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
    assert grips[0].s.length == 30 mm and grips[0].s.width == 16 mm
    assert grips[0].s.center.x - lid.body.bb.left == 25 mm
    assert lid.body.bb.right - grips[1].s.center.x == 25 mm
    assert title.t.size == 20 mm
    assert distance(title, grips[0]) >= 10 mm and distance(title, grips[1]) >= 10 mm
}
