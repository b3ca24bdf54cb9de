# Request (music): paddle castanets for a school music corner, cut from 6 mm beech ply.
# - Paddle: a 60 mm round head with a 110 mm long, 25 mm wide handle below it (round end, a 6 mm
#   hanging hole 10 mm from the end) and "OLE!" engraved filled, 10 mm tall, reading up the handle.
# - Two clappers: 55 mm discs, tied to each face of the paddle's head with elastic cord.
# - Head and clappers each have an ear at the top with two 4 mm cord holes 16 mm apart, 30 mm above
#   the disc's centre, so the holes of all three line up.
# - Each clapper is engraved with a ring of twelve filled 3 mm dots on a 36 mm circle around an
#   engraved five-pointed star 20 mm across.

thickness 6 mm

param spread = 16 mm, min = 12 mm, max = 24 mm

def shell(d=55 mm) -> solid {
    body = Hull(Circle(center=(0, 0), diameter=d), Circle(center=(-spread / 2, 30), radius=6),
                Circle(center=(spread / 2, 30), radius=6))
    hole cord {
        l = Circle(center=(-spread / 2, 30), diameter=4)
        r = Circle(center=(spread / 2, 30), diameter=4)
    }
}

def clapper() -> solid {
    s = shell(d=55 mm)
    drawing deco {
        dot = Circle(center=(18, 0), diameter=3, fill=true)
        dots = CircularPattern(dot, 12, (0, 0))
        star = Star(center=(0, 0), points=5, outer_radius=10, inner_radius=4)
    }
}

assembly castanets {
    solid paddle {
        head = shell(d=60 mm)
        handle = Slot(start=(0, -20), end=(0, -30 - 110 + 12.5), width=25)
        hole hang { c = Circle(center=(0, -30 - 110 + 10), diameter=6) }
        drawing word {
            t = Text("OLE!", (0, -85), size=10, rotation=90, font="sans:Bold", valign="middle",
                     fill=true)
        }
    }

    left = clapper()
    right = clapper()

    RightOf(left, paddle, gap=8)
    RightOf(right, left, gap=8)
    AlignTop(left, paddle)
    AlignTop(right, paddle)

    # the request's numbers
    assert paddle.handle.width == 25 mm, "handle 25 wide"
    assert -30 mm - paddle.handle.bb.bottom == 110 mm, "handle 110 below the head"
    assert paddle.hang.c.center.y - paddle.handle.bb.bottom == 10 mm, "hang hole 10 from the end"
    assert paddle.hang.c.diameter == 6 mm, "6 mm hang hole"
    assert paddle.head.cord.r.center.x - paddle.head.cord.l.center.x == 16 mm, "cord holes 16 apart"
    assert left.s.cord.r.center.x - left.s.cord.l.center.x == 16 mm, "cord holes 16 apart"
    assert paddle.head.cord.l.center.y == 30 mm and left.s.cord.l.center.y - left.s.body.center.y < 30.01 mm,
        "holes 30 above the centre"
    assert len(left.deco.dots) == 12, "twelve dots"
    assert left.deco.star.outer_radius * 2 == 20 mm, "star 20 across"
}
