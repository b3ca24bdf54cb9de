# Request: a curved piece of wooden toy railway that fits the common wooden-track sets, built
# up from a 6 mm ply base and three 3 mm ply strips glued on top (so the wheel grooves are
# 3 mm deep). Track 40 mm wide, curving 45 degrees about a 180 mm centre-line radius. Two
# grooves 6 mm wide whose centres are 25 mm apart, 12.5 mm either side of the centre line,
# so the strips are: an inner rail strip (160 to 164.5 mm radius), a middle strip (170.5 to
# 189.5) and an outer rail strip (195.5 to 200). The joint: at the 45-degree end a peg (a
# 7 mm neck, a 12 mm round head whose centre is 13 mm out from the end face, along the
# track); at the 0-degree end a socket of the same shape 0.5 mm larger, cut into the track.
# Peg and socket go through the base and the middle strip, so a peg drops in from above.

thickness 3 mm

Rc = 180 mm
track_w = 40 mm
span = 45 deg
groove = 6 mm
pitch = 25 mm
neck_w = 7 mm
head_d = 12 mm
reach = 13 mm
fit = 0.5 mm

r_in = Rc - track_w / 2
r_out = Rc + track_w / 2
g_in = Rc - pitch / 2      # the inner groove's centre
g_out = Rc + pitch / 2     # the outer groove's centre

# the centre line's point at the 45-degree end, and the track's direction there
px = Rc * cos(span)
py = Rc * sin(span)
tx = -sin(span)
ty = cos(span)

def layer(a, b, joint=false, ply=3 mm) -> solid {
    thickness ply
    arc = Sector(center=(0, 0), radius=b, inner_radius=a, start_angle=0 deg, end_angle=span)
    if joint {
        solid peg {
            neck = Rectangle(start=(px - tx, py - ty), end=(px + reach * tx, py + reach * ty),
                             width=neck_w)
            head = Circle(center=(px + reach * tx, py + reach * ty), diameter=head_d)
        }
        hole socket {
            neck = Rectangle(start=(Rc, -1 mm), end=(Rc, reach), width=neck_w + fit)
            head = Circle(center=(Rc, reach), diameter=head_d + fit)
        }
    }
}

assembly curve {
    base = layer(a=r_in, b=r_out, joint=true, ply=6 mm)
    inner_rail = layer(a=r_in, b=g_in - groove / 2)
    middle = layer(a=g_in + groove / 2, b=g_out - groove / 2, joint=true)
    outer_rail = layer(a=g_out + groove / 2, b=r_out)

    # flat: the strips nest where they lie on the base; the base below them on the sheet
    Below(base, outer_rail, gap=10)

    # assembled: the base on z = 0, the strips on it
    Place(base, position=(0, 0, 0), face="up")
    Place(inner_rail, position=(0, 0, 6 mm), face="up")
    Place(middle, position=(0, 0, 6 mm), face="up")
    Place(outer_rail, position=(0, 0, 6 mm), face="up")

    assert base.arc.width == 40 mm, "track 40 mm wide"
    assert middle.arc.inner_radius - inner_rail.arc.radius == 6 mm, "inner groove 6 mm"
    assert outer_rail.arc.inner_radius - middle.arc.radius == 6 mm, "outer groove 6 mm"
    assert g_out - g_in == 25 mm, "groove centres 25 mm apart"
    assert inner_rail.arc.radius == 164.5 mm and middle.arc.inner_radius == 170.5 mm
    assert middle.arc.radius == 189.5 mm and outer_rail.arc.inner_radius == 195.5 mm
    assert base.socket.head.diameter - base.peg.head.diameter == 0.5 mm
}
