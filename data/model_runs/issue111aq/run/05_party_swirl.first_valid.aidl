# Request (parties): a hanging ceiling swirl for a 40th birthday, cut from 1.5 mm
# polypropylene sheet. It is a 12 mm wide strip wound as an Archimedean spiral (12 mm per
# turn): the spiral cut starts 25 mm from the centre and winds out anticlockwise to the
# outer turn, whose outside edge reaches 100 mm from the centre (a 200 mm swirl); the strip
# ends square at the top (a radial end). The centre keeps a 4 mm hanging hole 16 mm above
# the centre and "40" cut through as 14 mm bold stencil figures, centred 2 mm below the
# centre. A 4 mm hole in the strip's outer end, 6 mm in from its end and centred across
# the strip, takes a foil star.

thickness 1.5 mm

r0 = 25 mm          # the spiral cut's start
pitch = 12 mm       # per turn = the strip's width
R = 100 mm          # outside edge of the outer turn at its end
turns = (R - r0) / pitch            # 6.25 turns of the outside edge
T = turns * 360                      # its end angle in degrees (2250: at the top)

def rr(a) = r0 + pitch * a / 360
def sx(a) = rr(a) * cos(a * 1 deg)
def sy(a) = rr(a) * sin(a * 1 deg)

solid swirl {
    # the outer turn's outside edge, from one turn before the end to the end, closed by
    # the radial end of the strip
    outline = Polygon([(sx(a), sy(a)) for a in range(T - 360, T + 1, 5)])
    cut spiral {
        s = Polyline([(sx(a), sy(a)) for a in range(0, T - 360 + 1, 5)])
    }
    hole hang { c = Circle(center=(0, 16), diameter=4) }
    hole figures {
        t = Text("40", position=(0, -2), size=14, font="sans:Bold", valign="middle", stencil=true)
    }
    hole star_eye {
        c = Circle(center=((R - pitch / 2) * cos((T - 360) * 1 deg - 6 mm / (R - pitch / 2) * 1 rad),
                           (R - pitch / 2) * sin((T - 360) * 1 deg - 6 mm / (R - pitch / 2) * 1 rad)),
                   diameter=4)
    }
    assert rr(T) == 100 mm, "outer edge reaches 100 mm"
    assert rr(T) - rr(T - 360) == 12 mm, "12 mm strip"
    assert outline.bb.top == 100 mm, "the strip ends at the top"
    assert spiral.s.points[0].x == 25 mm, "the cut starts 25 mm from the centre"
}
