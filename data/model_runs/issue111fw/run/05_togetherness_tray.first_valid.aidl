# REQUEST (holidays): a Lunar New Year "tray of togetherness" for sweets, laser-cut and
# glued in layers. Five parts, all octagons 330 mm across flats (flats at top and bottom):
# a 6 mm ply base; two 6 mm ply pocket layers, identical, stacked on it to make the
# compartments 12 mm deep: a 80 mm round centre pocket and 8 pockets round it, one facing
# each flat, cut from the ring between 45 and 145 mm from the centre and split by 10 mm ribs
# (each pocket is its 45 deg ring piece shrunk 5 mm all round); a 3 mm red acrylic lid with
# "HAPPY NEW YEAR" engraved along the top (10 mm letters on a 140 mm radius) and "2027 YEAR
# OF THE GOAT" along the bottom (7 mm, reading the right way up); and a knob glued on the
# lid's centre, an 8-pointed 6 mm ply star 50 mm across, rounded tips R3. Shown stacked.

units mm

t = 6 mm
flats = 330 mm

def pocket_layer() -> solid {
    thickness t
    body = RegularPolygon(center=(0, 0), across_flats=flats, sides=8, rotation=22.5 deg)
    hole pockets {
        centre = Circle(center=(0, 0), diameter=80)
        for k in range(8) {
            p = Inset(Sector(center=(0, 0), radius=145, inner_radius=45,
                             start_angle=-22.5 deg + k * 45 deg,
                             end_angle=22.5 deg + k * 45 deg), 5)
        }
    }
}

assembly tray {
    solid base {
        thickness t
        body = RegularPolygon(center=(0, 0), across_flats=flats, sides=8, rotation=22.5 deg)
    }
    lower = pocket_layer()
    upper = pocket_layer()
    solid lid {
        thickness 3 mm
        body = RegularPolygon(center=(0, 0), across_flats=flats, sides=8, rotation=22.5 deg)
        drawing words {
            ring = Circle(center=(0, 0), radius=140, construction=true)
            top = Text("HAPPY NEW YEAR", along=ring, size=10)
            bottom = Text("2027 YEAR OF THE GOAT", along=ring, size=7, flip=true)
        }
    }
    solid knob {
        thickness t
        star = Star(center=(0, 0), points=8, outer_radius=25, inner_radius=17, tip_radius=3)
    }

    # flat, for cutting: a row
    RightOf(lower, base, gap=10)
    AlignCenterY(lower, base)
    RightOf(upper, lower, gap=10)
    AlignCenterY(upper, lower)
    RightOf(lid, upper, gap=10)
    AlignCenterY(lid, upper)
    RightOf(knob, lid, gap=10)
    AlignCenterY(knob, lid)

    # 3D: stacked
    Place(base, position=(0, 0, 0))
    Place(lower, on=base, position=(0, 0))
    Place(upper, on=lower, position=(0, 0))
    Place(lid, on=upper, position=(0, 0))
    Place(knob, on=lid, position=(0, 0))
}

# the request's numbers
assert tray.base.body.across_flats == 330 mm and tray.lid.body.across_flats == 330 mm, "330 across flats"
assert tray.lower.body.across_flats == 330 mm, "layers 330 across flats"
assert len(tray.lower.pockets.p) == 8, "8 pockets round the centre"
assert tray.lower.pockets.centre.diameter == 80 mm, "80 mm centre pocket"
assert 2 * t == 12 mm, "compartments 12 mm deep (two 6 mm layers)"
assert tray.lower.pockets.p[0].bb.right == 145 mm - 5 mm, "pockets reach 140 mm out"
assert tray.lower.body.apothem - (145 mm - 5 mm) >= 20 mm, "an outer wall of 20 mm or more"
assert tray.knob.star.outer_radius * 2 == 50 mm, "knob 50 mm across"
assert tray.lid.words.bb.top < tray.lid.body.bb.top - 3 mm, "the words stay on the lid"
assert tray.lid.words.bb.bottom > tray.lid.body.bb.bottom + 3 mm, "the words stay on the lid"
