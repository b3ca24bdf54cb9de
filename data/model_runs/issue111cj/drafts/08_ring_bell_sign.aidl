# Request: a two-tone "PLEASE RING" sign for beside a front door, in two layers of 3 mm
# acrylic glued together: a black back plate and a white front plate of the same outline,
# 200 x 80 mm with r 12 corners. Both have a 22 mm hole for a round bell push, its centre
# 70 mm right of the sign's centre, and two 3.5 mm screw holes on the centre line 90 mm
# either side of the centre; the front's screw holes countersunk for 7 mm heads. "PLEASE RING"
# is cut through the front as bold stencil letters 13 mm tall (at most 110 mm long), centred
# 20 mm left of the sign's centre, with a cut-out arrow between the words and the bell push,
# pointing at it, so the black shows through.

units mm
thickness 3 mm

def layer(front=false) -> solid {
    body = RoundedRectangle(center=(0, 0), width=200, height=80, corner_radius=12)
    hole bell {
        c = Circle(center=(70, 0), diameter=22)
    }
    hole screws {
        l = Circle(center=(-90, 0), diameter=3.5)
        r = Circle(center=(90, 0), diameter=3.5)
    }
    if front {
        hole words {
            t = Text("PLEASE RING", position=(-20, 0), size=13, font="sans:Bold",
                     valign="middle", stencil=true, max_width=110)
        }
        hole arrow {
            a = Polygon([(38, -3), (47, -3), (47, -8), (56, 0), (47, 8), (47, 3), (38, 3)])
        }
        Countersink([screws.l, screws.r], diameter=7)
    }
}

assembly sign {
    back = layer()
    front = layer(front=true)

    # flat on the sheet
    Above(front, back, gap=10)
    AlignLeft(front, back)

    # in 3D: the back on the wall, the front glued on it
    Place(back, position=(0, 0, 0))
    Place(front, position=(0, 0, 3))

    assert front.body.width == 200 mm and front.body.height == 80 mm
    assert front.bell.c.diameter == 22 mm
    assert front.bell.c.center.x - front.body.center.x == 70 mm
    assert front.screws.r.center.x - front.body.center.x == 90 mm
    assert front.body.center.x - front.screws.l.center.x == 90 mm
    assert front.words.t.bb.width <= 110 mm
    assert front.words.t.position.x - front.body.center.x == -20 mm
    assert front.arrow.a.bb.right < front.bell.c.center.x - 11 mm, "arrow clear of the bell hole"
    assert front.arrow.a.bb.left > front.words.t.bb.right, "arrow clear of the words"
}
