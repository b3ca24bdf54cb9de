# Request: "I want a free-standing room divider screen made of hexagonal tiles in 3 mm birch
# ply, joined by little H-clips. Each tile is a regular hexagon 120 mm across the flats (flats
# at top and bottom), with a 3.2 mm wide notch 10 mm deep in the middle of each of its six
# edges, square to the edge, for the clips. In each tile a fretwork flower: six elliptical
# petals 36 mm long and 12 mm wide pointing at the corners, their inner ends 8 mm from the
# centre, and a 10 mm hole in the centre. The clip is an H: a 20 mm long waist 3.2 mm high
# (it sits in two butted notches) between two flanges 34 mm long and 4 mm high. Show two
# tiles joined at one edge by a clip."

units mm
thickness 3 mm

param af = 120 mm, min = 90, max = 200   # the tile across its flats
notch_w = 3.2 mm
notch_d = 10 mm
petal_len = 36 mm
petal_w = 12 mm
petal_in = 8 mm
flange_len = 34 mm
flange_h = 4 mm

def tile() -> solid {
    hexa = RegularPolygon(center=(0, 0), across_flats=af, sides=6)
    # one notch in the middle of the top edge, copied round to all six edges
    hole notch {
        n = Rectangle(center=(0, af / 2 - notch_d / 2), width=notch_w, height=notch_d)
        o = Rectangle(center=(0, af / 2 + 0.5), width=notch_w, height=1, overrun=true)
    }
    notches = CircularPattern(notch, 6, hexa.center)
    # the fretwork flower: petals pointing at the corners (the first corner is on +x)
    hole petal {
        e = Ellipse(center=(petal_in + petal_len / 2, 0), rx=petal_len / 2, ry=petal_w / 2)
    }
    petals = CircularPattern(petal, 6, hexa.center)
    hole eye { c = Circle(center=(0, 0), diameter=10) }
}

def h_clip() -> solid {
    waist = Rectangle(center=(0, 0), width=2 * notch_d, height=notch_w)
    upper = Rectangle(center=(0, notch_w / 2 + flange_h / 2), width=flange_len, height=flange_h)
    lower = Rectangle(center=(0, -notch_w / 2 - flange_h / 2), width=flange_len, height=flange_h)
}

assembly screen {
    a = tile()
    b = tile()
    clip = h_clip()
    # on the sheet: side by side, the clip below
    RightOf(b, a, gap=6)
    AlignCenterY(b, a)
    Below(clip, a, gap=6)
    AlignCenterX(clip, a)
    # assembled: b stands on a's top edge, the clip across the seam in the two notches
    Place(a, position=(0, 0, 0))
    Place(b, position=(0, af, 0))
    Place(clip, position=(-1.5, af / 2, 1.5), rotation=(90 deg, 0, 90 deg))

    # the request's numbers
    assert abs(a.hexa.bb.height - 120 mm) < 0.01, "tile 120 mm across the flats"
    assert len(a.notches) == 6 and len(a.petals) == 6, "six notches, six petals"
    assert abs(a.notch.n.bb.width - 3.2 mm) < 0.01, "notch 3.2 mm wide"
    assert abs((a.hexa.bb.top - a.notch.n.bb.bottom) - 10 mm) < 0.01, "notch 10 mm deep"
    assert abs(a.petal.e.bb.width - 36 mm) < 0.01 and abs(a.petal.e.bb.height - 12 mm) < 0.01,
        "petal 36 x 12"
    assert abs((a.petal.e.bb.left - a.hexa.center.x) - 8 mm) < 0.01, "petal starts 8 mm out"
    assert abs(a.eye.c.diameter - 10 mm) < 0.01, "10 mm centre hole"
    assert abs(clip.waist.bb.width - 20 mm) < 0.01 and abs(clip.waist.bb.height - 3.2 mm) < 0.01,
        "waist 20 x 3.2"
    assert abs(clip.upper.bb.width - 34 mm) < 0.01 and abs(clip.upper.bb.height - 4 mm) < 0.01,
        "flanges 34 x 4"
}
