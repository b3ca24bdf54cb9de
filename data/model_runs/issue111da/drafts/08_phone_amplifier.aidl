# Request (gifts): a passive phone amplifier as a present for my dad, five glued layers of 6 mm
# ply, each 160 x 100 mm with 15 mm corners. The three middle layers have a flared horn cut
# through them: a throat 90 mm wide whose back edge is 20 mm in from the back, flaring out in a
# smooth curve to 124 mm wide where it opens in the front edge. The top layer has an 80 x 12 mm
# round-ended slot for the phone, its middle 28 mm in from the back edge, over the throat, and
# "HAPPY 60TH DAD" engraved filled (sans bold, 9 mm) centred 35 mm in from the front edge. The
# base is plain. The phone stands in the slot on the base, its speaker in the throat.

thickness 6 mm

t = 6 mm
w = 160 mm
d = 100 mm
corner = 15 mm

# the horn's right half (x >= 0), from the throat's back edge round to past the front edge
half_horn = [(0, 30), (45, 30), (46, 18), (49, 5), (53, -10), (57.5, -26), (62, -50), (63, -56),
             (0, -56)]

def layer() -> solid {
    body = RoundedRectangle(center=(0, 0), width=w, height=d, corner_radius=corner)
}

def horn_layer() -> solid {
    body = RoundedRectangle(center=(0, 0), width=w, height=d, corner_radius=corner)
    hole horn {
        h = Spline(mirror(half_horn, about="y"), closed=true, corners=[1, 7, 9, 15])
    }
}

assembly amplifier {
    base = layer()
    horn1 = horn_layer()
    horn2 = horn_layer()
    horn3 = horn_layer()

    solid top {
        body = RoundedRectangle(center=(0, 0), width=w, height=d, corner_radius=corner)
        hole phone {
            s = Slot(center=(0, d / 2 - 28 mm), length=80 mm, width=12 mm)
        }
        drawing words {
            g = Text("HAPPY 60TH DAD", position=(0, -d / 2 + 35 mm), size=9 mm, font="sans:Bold",
                     valign="middle", fill=true)
        }
    }

    # on the sheet: a row and a second row
    RightOf(horn1, base, gap=8)
    RightOf(horn2, horn1, gap=8)
    Below(horn3, base, gap=8)
    RightOf(top, horn3, gap=8)
    AlignCenterY(horn1, base)
    AlignCenterY(horn2, base)
    AlignCenterY(top, horn3)
    AlignLeft(horn3, base)

    # in 3D: stacked
    Place(base, position=(0, 0, 0))
    Place(horn1, position=(0, 0, t))
    Place(horn2, position=(0, 0, 2 * t))
    Place(horn3, position=(0, 0, 3 * t))
    Place(top, position=(0, 0, 4 * t))

    assert base.body.width == 160 mm and base.body.height == 100 mm, "160 x 100 layers"
    assert horn1.horn.h.points[1].x - horn1.horn.h.points[15].x == 90 mm, "throat 90 mm"
    assert horn1.body.bb.top - horn1.horn.h.points[1].y == 20 mm, "throat 20 mm from the back"
    assert horn1.horn.h.points[6].x - horn1.horn.h.points[10].x == 124 mm, "124 mm at the front"
    assert horn1.horn.h.points[6].y == horn1.body.bb.bottom, "measured on the front edge"
    assert top.phone.s.length == 80 mm and top.phone.s.width == 12 mm, "slot 80 x 12"
    assert top.body.bb.top - top.phone.s.center.y == 28 mm, "slot 28 mm from the back"
    assert top.words.g.position.y - top.body.bb.bottom == 35 mm, "text 35 mm from the front"
    assert top.words.g.size == 9 mm, "9 mm letters"
}
