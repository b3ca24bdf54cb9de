# Request (music): an elastic-cord guitar capo from 6 mm birch ply, three layers glued into
# an 18 mm thick bar. Each layer is 80 mm long and 16 mm tall at its ends; the underside is
# hollowed to the fingerboard's 12 inch (305 mm) radius (about 2.6 mm deep in the middle);
# the four outer corners rounded 3 mm. A 4 mm cord hole 7 mm from the left end, 2 mm above
# the middle line; three 3 mm wide, 6 mm deep cord notches in the top edge at 26, 31 and 36
# mm right of the middle, for three tensions. The middle layer's underside is cut back a
# further 2 mm over its middle 56 mm, following the curve, as a channel for a leather pad
# glued between the two outer layers. "CAPO" engraved filled, 6 mm bold, on the front layer.

thickness 6 mm

L = 80 mm
H = 16 mm
R = 305 mm
sag = R - sqrt(R ** 2 - (L / 2) ** 2)
pad_len = 56 mm
pad_depth = 2 mm
notch_xs = [26 mm, 31 mm, 36 mm]

def layer(core=false, label=false) -> solid {
    top = Line((L / 2, H / 2), (-L / 2, H / 2))
    lt = Line((-L / 2, H / 2), (-L / 2, -H / 2))
    bottom = Arc(start=(-L / 2, -H / 2), through=(0, -H / 2 + sag), end=(L / 2, -H / 2))
    rt = Line((L / 2, -H / 2), (L / 2, H / 2))
    Fillet([[top, rt], [top, lt], bottom.start, bottom.end], 3)
    hole cord { c = Circle(center=(-L / 2 + 7 mm, 2), diameter=4) }
    for k in range(len(notch_xs)) {
        hole notch { r = Rectangle(bottom_left=(notch_xs[k] - 1.5 mm, H / 2 - 6 mm), width=3, height=7) }
    }
    if core {
        hole pad {
            channel = Intersect(Rectangle(center=(0, -H / 2), width=pad_len, height=12),
                                Circle(center=(0, -H / 2 + sag - R + pad_depth), radius=R))
        }
    }
    if label {
        drawing name {
            word = Text("CAPO", position=(-4, 0), size=6, font="sans:Bold", valign="middle", fill=true)
        }
    }
}

assembly capo {
    back = layer()
    middle = layer(core=true)
    front = layer(label=true)

    # on the sheet: one under the other
    Fixed(back)
    Below(middle, back, gap=5)
    AlignLeft(middle, back)
    Below(front, middle, gap=5)
    AlignLeft(front, middle)

    # glued up
    Place(back, position=(0, 0, 0))
    Place(middle, position=(0, 0, 6 mm))
    Place(front, position=(0, 0, 12 mm))

    # the request's numbers
    assert back.top.length == 80 mm, "80 mm long"
    assert back.rt.length == 16 mm, "16 mm tall at the ends"
    assert abs(sag - 2.6 mm) < 0.1 mm, "hollow about 2.6 mm deep"
    assert back.cord.c.center.x - back.lt.start.x == 7 mm, "cord hole 7 mm from the left end"
    assert len(back.notch) == 3, "three notches"
    assert back.notch[0].r.bb.center_x - back.top.midpoint.x == 26 mm, "first notch 26 mm right of the middle"
    assert back.notch[2].r.bb.center_x - back.top.midpoint.x == 36 mm, "last notch 36 mm right of the middle"
    assert back.top.midpoint.y - back.notch[1].r.bb.bottom == 6 mm, "notches 6 deep"
    assert middle.pad.channel.bb.width == 56 mm, "pad channel over the middle 56 mm"
}
