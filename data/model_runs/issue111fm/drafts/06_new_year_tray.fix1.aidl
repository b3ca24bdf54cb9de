# Request: a Lunar New Year "tray of togetherness" (candy box) for 2027, the Year of the Goat,
# glued up from 9 mm birch ply. An octagon 260 mm across the flats (flats at top and bottom).
# A solid base; two identical pocket layers on it (18 mm deep pockets): a round middle
# pocket 90 mm across and eight ring-segment pockets between R52 and R115, one facing each
# flat, the walls between them 39 degrees of the circle apart (19.5 degrees either side of each
# pocket's middle), every pocket corner rounded R4. A lift-off lid, the same octagon,
# engraved with "HAPPY NEW YEAR" over the top and "YEAR OF THE GOAT" under the bottom of an
# 80 mm circle (letters 14 and 10 mm), and an engraved ring of R60 round the knob. The knob: a
# small octagon 50 mm across the flats glued on the lid's centre, with the character 福
# (fortune) engraved filled on it, 24 mm.

t = 9 mm
thickness t

# FIX after the first valid program: a left-over `def octagon` nothing called (W0117) deleted

def pocket_layer() -> solid {
    body = RegularPolygon(center=(0, 0), across_flats=260, sides=8, rotation=22.5 deg)
    hole middle {
        c = Circle(center=(0, 0), diameter=90)
    }
    for k in range(8) {
        hole cell {
            s = Sector(center=(0, 0), radius=115, start_angle=k * 45 deg - 19.5 deg,
                       end_angle=k * 45 deg + 19.5 deg, inner_radius=52)
            Fillet(4)
        }
    }
    Rigid(self)
}

assembly tray {
    solid base {
        body = RegularPolygon(center=(0, 0), across_flats=260, sides=8, rotation=22.5 deg)
    }
    lower = pocket_layer()
    upper = pocket_layer()
    solid lid {
        body = RegularPolygon(center=(0, 0), across_flats=260, sides=8, rotation=22.5 deg)
        drawing words {
            ring = Circle(center=(0, 0), radius=80, construction=true)
            top = Text("HAPPY NEW YEAR", along=ring, size=14)
            bottom = Text("YEAR OF THE GOAT", along=ring, size=10, flip=true)
            knob_ring = Circle(center=(0, 0), radius=60)
        }
        Rigid(self)
    }
    solid knob {
        body = RegularPolygon(center=(0, 0), across_flats=50, sides=8, rotation=22.5 deg)
        drawing mark {
            fu = Text("福", position=(0, 0), size=24, valign="middle", font="Droid Sans Fallback",
                      fill=true)
        }
        Rigid(self)
    }

    # flat on the sheet
    RightOf(lower, base, gap=10)
    AlignTop(lower, base)
    Below(upper, base, gap=10)
    AlignLeft(upper, base)
    RightOf(lid, upper, gap=10)
    AlignTop(lid, upper)
    RightOf(knob, lower, gap=10)
    AlignTop(knob, lower)

    # stacked in 3D
    Place(base, position=(0, 0, 0), face="up")
    Place(lower, position=(0, 0, 9), face="up")
    Place(upper, position=(0, 0, 18), face="up")
    Place(lid, position=(0, 0, 27), face="up")
    Place(knob, position=(0, 0, 36), face="up")

    assert base.body.across_flats == 260 mm, "260 across the flats"
    assert len(upper.cell) == 8, "eight pockets round the middle"
    assert upper.middle.c.diameter == 90 mm, "middle pocket 90"
    assert upper.cell[0].s.inner_radius == 52 mm and upper.cell[0].s.radius == 115 mm, "pockets R52 to R115"
    assert distance(upper.cell[0], upper.cell[1]) >= 5 mm, "walls between pockets at least 5 mm"
    assert distance(upper.cell[0], upper.middle) >= 5 mm, "wall round the middle pocket"
    assert upper.body.apothem - upper.cell[0].s.radius >= 12 mm, "outer wall at least 12 mm"
    assert knob.body.across_flats == 50 mm, "knob 50 across"
    assert knob.mark.bb.width < 45 mm and knob.mark.bb.height < 45 mm, "fortune character on the knob"
    assert lid.words.knob_ring.radius - knob.body.radius >= 5 mm, "ring clear of the knob"
}
