# Request (parties): popcorn boxes for a film-night party, cut and scored on the laser from
# 0.5 mm white card (350 gsm), the net fitting an A3 card (420 x 297 mm). A tapered box: a
# 60 x 60 mm base, flaring to an 80 x 80 mm mouth, each wall 110 mm along its slant. One net:
# the base in the middle, the four walls hinged on its edges, 12 mm glue flaps on both slanted
# edges of the front and back walls (their ends tapered so they clear the side walls). Score
# (engrave) every fold: the base's four edges and the four flap hinges. "POPCORN" in bold
# filled letters 10 mm high on the front and back walls, upright when the box is folded, and
# a filled 5-point star 16 mm across on each side wall.

units mm
thickness 0.5 mm

B = 60 mm       # base
M = 80 mm       # mouth
S = 110 mm      # wall, along the slant in the net
F = 12 mm       # glue flap
FLARE = (M - B) / 2
LEG = sqrt(FLARE ** 2 + S ** 2)
# along the front wall's left leg (from the base corner out) and its outward normal
DX = -FLARE / LEG
DY = -S / LEG
NX = -S / LEG
NY = FLARE / LEG

solid net {
    base = Rectangle(center=(0, 0), width=B, height=B)
    front = Trapezoid(center=(0, -B / 2 - S / 2), bottom_width=M, top_width=B, height=S)
    back = Trapezoid(center=(0, B / 2 + S / 2), bottom_width=B, top_width=M, height=S)
    left = Trapezoid(center=(-B / 2 - S / 2, 0), bottom_width=B, top_width=M, height=S,
                     rotation=90 deg)
    right = Trapezoid(center=(B / 2 + S / 2, 0), bottom_width=B, top_width=M, height=S,
                      rotation=-90 deg)

    # glue flap on the front wall's left leg, from the base corner (-30, -30) out to (-40, -140)
    c0 = (-B / 2, -B / 2)
    c1 = (-M / 2, -B / 2 - S)
    flap_fl = Polygon([(c0[0] + 3 * DX, c0[1] + 3 * DY),
                       (c0[0] + 15 * DX + F * NX, c0[1] + 15 * DY + F * NY),
                       (c1[0] - 10 * DX + F * NX, c1[1] - 10 * DY + F * NY),
                       c1])
    vaxis = Line((0, -200), (0, 200), construction=true)
    haxis = Line((-200, 0), (200, 0), construction=true)
    flap_fr = Mirrored(flap_fl, about=vaxis)
    flap_bl = Mirrored(flap_fl, about=haxis)
    flap_br = Mirrored(flap_fr, about=haxis)

    drawing scores {
        e0 = Line((-B / 2, -B / 2), (B / 2, -B / 2))
        e1 = Line((B / 2, -B / 2), (B / 2, B / 2))
        e2 = Line((B / 2, B / 2), (-B / 2, B / 2))
        e3 = Line((-B / 2, B / 2), (-B / 2, -B / 2))
        h0 = Line((-B / 2, -B / 2), (-M / 2, -B / 2 - S))
        h1 = Line((B / 2, -B / 2), (M / 2, -B / 2 - S))
        h2 = Line((-B / 2, B / 2), (-M / 2, B / 2 + S))
        h3 = Line((B / 2, B / 2), (M / 2, B / 2 + S))
    }

    drawing words {
        tf = Text("POPCORN", position=(0, -B / 2 - S / 2), size=10, font="sans:Bold",
                  valign="middle", rotation=180 deg, fill=true)
    }
    drawing words_back {
        tb = Text("POPCORN", position=(0, B / 2 + S / 2), size=10, font="sans:Bold",
                  valign="middle", fill=true)
    }
    drawing stars {
        sl = Star(center=(-B / 2 - S / 2, 0), points=5, outer_radius=8, inner_radius=3.5,
                  rotation=90 deg, fill=true)
        sr = Star(center=(B / 2 + S / 2, 0), points=5, outer_radius=8, inner_radius=3.5,
                  rotation=-90 deg, fill=true)
    }

    # the request's numbers
    assert base.width == 60 mm and base.height == 60 mm, "base 60 x 60"
    assert front.bottom_width == 80 mm and back.top_width == 80 mm, "mouth 80"
    assert front.height == 110 mm, "walls 110 along the slant"
    assert distance(flap_fl.points[1], front.bottom_left) > 0 mm, "flap off the corner"
    assert self.bb.width <= 420 mm and self.bb.height <= 297 mm, "fits an A3 card"
    assert words.bb.width <= B, "words fit the wall's narrow end"
    assert sl.outer_radius * 2 == 16 mm, "stars 16 across"
}
