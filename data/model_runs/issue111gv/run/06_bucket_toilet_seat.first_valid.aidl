# Request: a camping toilet seat and lid for a 20 litre bucket (rim 300 mm outside, 280 mm
# inside), from 12 mm exterior ply. The seat: an oval 360 mm wide and 400 mm long (the
# bucket's centre 10 mm behind the oval's), its back cut straight 160 mm behind the oval's
# centre for the hinges, the back corners rounded R15; the opening an oval 230 x 260 mm
# round the bucket's centre. Under it a locating ring, 276 mm across (2 mm clear of the
# rim's inside), with the same opening, glued on, so the seat cannot slide off. The lid:
# the seat's outline with a finger notch R18 at the front, "CAMP THRONE" engraved filled,
# 30 mm high, in the middle. Two butt hinges: 3.5 mm screw holes at x = 90 and 110 mm
# each side, 10 mm in from the straight back, the same on the seat and the lid.

thickness 12 mm

ply = 12 mm
bucket_y = -10 mm       # the bucket's centre, from the oval's centre
back_y = 160 mm

def oval_top() = Intersect(Ellipse(center=(0, 0), rx=180, ry=200),
                           Rectangle(corner=(-200, -210), opposite=(200, back_y)))

def hinge_holes() -> hole {
    for x in [-110 mm, -90 mm, 90 mm, 110 mm] {
        c = Circle(center=(x, back_y - 10 mm), diameter=3.5)
    }
}

assembly toilet {
    solid seat {
        body = oval_top()
        hole opening { o = Ellipse(center=(0, bucket_y), rx=115, ry=130) }
        hinges = hinge_holes()
        Fillet(15)
    }

    solid ring {
        rim = Circle(center=(0, bucket_y), diameter=276)
        hole opening { o = Ellipse(center=(0, bucket_y), rx=115, ry=130) }
    }

    solid lid {
        body = oval_top()
        hole notch { c = Circle(center=(0, -200), radius=18) }
        hinges = hinge_holes()
        drawing words {
            t = Text("CAMP THRONE", position=(0, 0), size=30, font="serif:Bold",
                     valign="middle", fill=true)
        }
        Fillet(15)
    }

    Place(ring, position=(0, 0, 0))
    Place(seat, position=(0, 0, ply))
    Place(lid, position=(0, 0, 2 * ply))

    # flat on the sheet: in a row
    RightOf(ring, seat, gap=10)
    AlignBottom(ring, seat)
    RightOf(lid, ring, gap=10)
    AlignBottom(lid, seat)

    assert seat.body.bb.width == 360 mm
    assert back_y - seat.body.bb.bottom == 160 mm + 200 mm, "cut 160 behind the oval's centre"
    assert seat.opening.o.rx * 2 == 230 mm and seat.opening.o.ry * 2 == 260 mm
    assert ring.rim.diameter == 276 mm, "2 mm clear of the 280 mm rim inside"
    assert ring.rim.center.y - seat.opening.o.center.y == 0 mm
    assert lid.notch.c.radius == 18 mm
    assert len(seat.hinges.c) == 4 and len(lid.hinges.c) == 4
    assert back_y - seat.hinges.c[0].center.y == 10 mm
    assert lid.words.t.size == 30 mm
    # the words, 318 mm long at 30 mm, keep 15 mm from the lid's edge (the oval is 360 wide there)
    assert lid.words.bb.width <= lid.body.bb.width - 30 mm, "the words fit inside the lid"
}
