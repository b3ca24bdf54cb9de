# Request: a sign for the village pond: "PLEASE DO NOT FEED THE DUCKS". A 6 mm ply backing 240 x 320
# (R15) screwed to a post by four 5 mm countersunk screws (10 mm heads) 15 mm in from each side.
# In the top part, centred 55 mm above the middle, a prohibition sign cut from 3 mm red acrylic:
# a ring 180 OD, 16 wide, with a 16 wide bar across it at 45 deg from top left to bottom right.
# Inside it a swimming duck facing right (about 120 x 76) cut from 3 mm black acrylic with a
# 5 mm eye hole, glued on the backing; since the bar lies over it, the duck is cut in two along
# the bar with 1.5 mm clearance each side. Below, engraved filled in sans Bold: "PLEASE DO NOT"
# and "FEED THE DUCKS" (20 mm), and "BREAD MAKES THEM ILL" (10 mm).

thickness 6 mm

ring_y = 55 mm
gap = 1.5 mm
bar_w = 16 mm
# the bar's normal (towards the top right)
nx = cos(45 deg)

def duck(side=1) -> solid {
    thickness 3 mm
    body = Ellipse(center=(-10, -15), rx=42, ry=24)
    tail = Polygon([(-40, -5), (-62, 14), (-50, -25)])
    neck = Ellipse(center=(24, 5), rx=11, ry=16)
    head = Circle(center=(28, 22), radius=15)
    beak = Polygon([(40, 24), (58, 18), (40, 14)])
    hole eye { c = Circle(center=(30, 26), diameter=5) }
    # everything on the other side of the bar (and its clearance) is cut away
    hole other_side {
        r = Rectangle(center=(-side * (bar_w / 2 + gap + 100 mm) * nx,
                              -side * (bar_w / 2 + gap + 100 mm) * nx),
                      width=300, height=200, rotation=-45)
    }
}

assembly pond_sign {
    solid backing {
        body = RoundedRectangle(center=(0, 0), width=240, height=320, corner_radius=15)
        hole screw { c = Circle(center=(0, 0), diameter=5) }
        screws = CornerPattern(screw, body, inset=15)
        Countersink(screws, diameter=10)
        drawing words {
            l1 = Text("PLEASE DO NOT", position=(0, -80), size=20, font="sans:Bold", fill=true)
            l2 = Text("FEED THE DUCKS", position=(0, -112), size=20, font="sans:Bold", fill=true)
            l3 = Text("BREAD MAKES THEM ILL", position=(0, -138), size=10, font="sans:Bold",
                      fill=true)
        }
    }
    solid no_sign {
        thickness 3 mm
        solid ring {
            rim = Circle(center=(0, 0), diameter=180)
            hole bore { c = Circle(center=(0, 0), diameter=148) }
        }
        bar = Rectangle(center=(0, 0), width=150, height=bar_w, rotation=-45)
    }
    head_half = duck(side=1)
    tail_half = duck(side=-1)

    RightOf(no_sign, backing, gap=5)
    AlignTop(no_sign, backing)
    Below(head_half, no_sign, gap=5)
    AlignLeft(head_half, no_sign)
    Below(tail_half, head_half, gap=5)
    AlignLeft(tail_half, head_half)

    Place(backing, position=(0, 0, 0))
    Place(no_sign, position=(0, ring_y, 6))
    Place(head_half, position=(0, ring_y, 6))
    Place(tail_half, position=(0, ring_y, 6))

    assert backing.body.bb.width == 240 mm and backing.body.bb.height == 320 mm, "240 x 320"
    assert len(backing.screws) == 4, "four screws"
    assert backing.screws[0].c.center.x - backing.body.bb.left == 15 mm, "screws 15 in"
    assert backing.screws[0].c.center.y - backing.body.bb.bottom == 15 mm, "screws 15 up"
    assert no_sign.ring.rim.diameter == 180 mm, "ring 180 OD"
    assert (no_sign.ring.rim.diameter - no_sign.ring.bore.c.diameter) / 2 == 16 mm, "ring 16 wide"
    assert no_sign.bar.height == 16 mm, "bar 16 wide"
    assert head_half.eye.c.diameter == 5 mm, "5 mm eye"
    assert distance(backing.words, backing.screws) >= 3 mm, "words clear of the screws"
    # the duck inside the ring's bore, 55 above the middle: the words stay below the ring
    assert backing.words.bb.top <= ring_y - 90 mm - 5 mm, "words under the ring"
    # every point of the duck within the bore, 5 mm in
    assert max([distance(p, (0, 0)) for p in head_half.beak.points + tail_half.tail.points]) <=
        74 mm - 5 mm, "duck inside the bore"
}
