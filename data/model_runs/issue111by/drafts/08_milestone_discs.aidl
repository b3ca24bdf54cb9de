# Request: "A gift for new parents: twelve milestone discs for the baby's monthly photo,
# 3 mm birch ply, one per month. Each disc is 100 mm across with a scalloped edge: sixteen
# 16 mm scallops round an 84 mm disc, the valleys between them rounded r2. On each the
# month's number engraved filled, sans bold 40 mm tall, its middle 6 mm above the centre, and
# MONTH (for 1) or MONTHS under it, sans 9 mm, its middle 27 mm below the centre. A little
# stand 120 x 45 mm (r6) with a 14 x 3.3 mm slot in its middle in which a disc stands on its
# bottom scallop, and FIRST YEAR engraved 6 mm tall, 12 mm in front of the slot. On the sheet
# the discs in three rows of four, 110 mm apart."

units mm
thickness 3 mm

disc_r = 42 mm
scallop_d = 16 mm
months = 12
pitch = 110 mm

def milestone(month=1, x=0 mm, y=0 mm) -> solid {
    disc = Circle(center=(x, y), radius=disc_r)
    solid bump { c = Circle(center=(x + disc_r, y), diameter=scallop_d) }
    bumps = CircularPattern(bump, 16, disc.center)
    drawing words {
        num = Text(str(month), position=(x, y + 6), size=40, font="sans:Bold", valign="middle",
                   fill=true)
        unit = Text("MONTH" if month == 1 else "MONTHS", position=(x, y - 27), size=9,
                    font="sans", valign="middle", fill=true)
    }
    Fillet(2)
}

assembly milestones {
    for i in range(months) {
        d = milestone(month=i + 1, x=(i % 4) * pitch, y=-(i // 4) * pitch)
    }
    solid stand {
        base = RoundedRectangle(center=(0, 0), width=120, height=45, corner_radius=6)
        hole slot { s = Rectangle(center=(0, 0), width=14, height=3.3) }
        drawing label { t = Text("FIRST YEAR", position=(0, -12), size=6, valign="middle") }
    }
    Below(stand, d[8], gap=10)
    AlignLeft(stand, d[8])

    # assembled: the stand on the table, month 1 standing in its slot on its bottom scallop
    Place(stand, position=(0, 0, 0))
    # FIX after the first valid program: W0518 said d[0] touches nothing, 0.15 mm from the
    # stand: that is the slot's intended play (a false alarm: the disc stands on the table and
    # leans on a wall of the slot); leaning it 0.15 mm onto the slot's back wall, as a real
    # disc would, says so in the assembled view
    Place(d[0], position=(0, 1.5 + 0.15, disc_r + scallop_d / 2), rotation=(90 deg, 0, 0))
    for i in range(1, months) {
        Place(d[i], position=(-200 mm + (i % 4) * pitch, -120 mm - (i // 4) * pitch, 0))
    }

    # the request's numbers
    assert len(d) == 12, "twelve discs"
    assert abs(d[0].bb.width - 100 mm) < 0.01 and abs(d[0].bb.height - 100 mm) < 0.01,
        "100 mm across"
    assert len(d[0].bumps) == 16 and abs(d[0].bump.c.diameter - 16 mm) < 0.01, "16 scallops of 16"
    assert abs(d[0].disc.diameter - 84 mm) < 0.01, "84 mm disc"
    assert d[11].words.num.text == "12" and d[0].words.unit.text == "MONTH" and
        d[1].words.unit.text == "MONTHS", "the right words"
    assert abs(d[3].words.num.size - 40 mm) < 0.01 and abs(d[3].words.unit.size - 9 mm) < 0.01,
        "40 and 9 mm letters"
    assert abs((d[5].words.num.position.y - d[5].disc.center.y) - 6 mm) < 0.01, "number 6 up"
    assert abs((d[5].disc.center.y - d[5].words.unit.position.y) - 27 mm) < 0.01, "word 27 down"
    assert abs((d[1].disc.center.x - d[0].disc.center.x) - 110 mm) < 0.01 and
        abs((d[0].disc.center.y - d[4].disc.center.y) - 110 mm) < 0.01, "110 apart"
    # the words stay inside the plain disc, clear of the scallops
    assert d[11].words.num.bb.width < 2 * disc_r - 10 mm, "number fits"
    assert abs(stand.base.bb.width - 120 mm) < 0.01 and abs(stand.base.bb.height - 45 mm) < 0.01,
        "stand 120 x 45"
    assert abs(stand.slot.s.bb.width - 14 mm) < 0.01 and abs(stand.slot.s.bb.height - 3.3 mm) < 0.01,
        "slot 14 x 3.3"
    assert abs((stand.slot.s.center.y - stand.label.t.position.y) - 12 mm) < 0.01, "label 12 in front"
}
