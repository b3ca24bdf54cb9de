# Request (gifts): a hand mirror for my niece Clara, three layers of 3 mm walnut ply glued
# together round a 100 mm round acrylic mirror (3 mm thick). The outline: a 120 mm round
# head and a handle tapering from 32 mm wide at the head to 26 mm at its round end, 248 mm
# long overall, the joins rounded R10, a 6 mm hanging hole in the handle's end. The back
# layer is whole; the middle layer has a 100.4 mm opening for the mirror; the front layer
# has a 94 mm window (a 3 mm lip over the mirror's edge), a ring of 36 dots 2 mm across
# engraved filled round the window, and "Clara" engraved filled in a serif along the
# handle, 9 mm high, reading from the head down.

thickness 3 mm

head_d = 120 mm
mirror_d = 100 mm
window_d = 94 mm
dots = 36
dot_r = (window_d / 2 + head_d / 2) / 2     # midway across the front's rim

def layer(opening=0 mm, front=false) -> solid {
    head = Circle(center=(0, 0), diameter=head_d)
    # FIX after the first valid program: with the wide end circle at y = -70, below the
    # head, the R10 fillet ended on that circle's arc and left a visible waist (a kink each
    # side under the fillet; no message named it); the circle now sits inside the head, so
    # the straight taper meets the head and the fillet joins them smoothly
    grip = Hull(Circle(center=(0, -50), radius=16), Circle(center=(0, -175), radius=13))
    hole hang { h = Circle(center=(0, -175), diameter=6) }
    if opening > 0 mm {
        hole glass { g = Circle(center=(0, 0), diameter=opening) }
    }
    if front {
        drawing deco {
            for i in range(dots) {
                d = Circle(center=polar((0, 0), dot_r, i * 360 deg / dots), diameter=2, fill=true)
            }
            name = Text("Clara", position=(0, -122), size=9, rotation=-90 deg, font="serif",
                        valign="middle", fill=true)
        }
    }
    Fillet(10)
}

assembly hand_mirror {
    back = layer()
    middle = layer(opening=mirror_d + 0.4 mm)
    front = layer(opening=window_d, front=true)

    RightOf(middle, back, gap=5)
    AlignBottom(middle, back)
    RightOf(front, middle, gap=5)
    AlignBottom(front, middle)

    Place(back, position=(0, 0, 0))
    Place(middle, position=(0, 0, 3 mm))
    Place(front, position=(0, 0, 6 mm))

    assert back.head.diameter == 120 mm
    assert back.bb.height == 248 mm, "248 mm overall"
    assert middle.glass.g.diameter - 100 mm == 0.4 mm
    assert (mirror_d - front.glass.g.diameter) / 2 == 3 mm, "3 mm lip"
    assert back.hang.h.diameter == 6 mm
    assert len(front.deco.d) == 36 and front.deco.d[0].diameter == 2 mm
    assert distance(front.deco, front.glass) >= 1 mm and distance(front.deco, front.hang) >= 1 mm
    assert front.deco.name.size == 9 mm
}
