# Request: a rubber-duck pull for the bathroom's ceiling light cord, made of three layers
# of 3 mm birch ply glued into one 9 mm thick duck, 60 mm from tail tip to beak tip.
# The duck faces right on the front: an oval body 44 x 28, a round head 20 across, a beak
# and a tail pointing up and back. The middle layer carries the cord: a 3 mm channel runs
# from the top of the head down to an 8 mm pocket in the body that holds the knot (the
# 2.5 mm cord is knotted inside before gluing). Both outer layers get an engraved eye
# (filled, 3.2 mm) and an engraved wing (an oval 20 x 10). Every outline corner rounded R1.5.

units mm
thickness 3 mm

def duck_layer(s=1, core=false) -> solid {
    body = Ellipse(center=(0, 0), rx=22, ry=14)
    head = Circle(center=(s * 14, 18), radius=10)
    # FIX after the first valid program: the tips are Hulls with an R1.5 circle, so the
    # 60 mm length holds on the final (filleted) outline
    beak = Hull(Circle(center=(s * 30.5, 17), radius=1.5), Point(s * 21, 21), Point(s * 21, 13))
    tail = Hull(Circle(center=(-s * 26.5, 13.5), radius=1.5), Point(-s * 16, 6), Point(-s * 20, -2))
    if core {
        hole chan { c = Slot(start=(s * 12, 32), end=(s * 12, 0), width=3) }
        hole knot { k = Circle(center=(s * 12, 0), diameter=8) }
        AllowOverlap(chan, knot)   # FIX after the first valid program: one opening is meant
    } else {
        drawing marks {
            eye = Circle(center=(s * 16, 20), diameter=3.2, fill=true)
            wing = Ellipse(center=(-s * 4, 0), rx=10, ry=5, rotation=s * 15 deg)
        }
    }
    Fillet(1.5)
}

assembly duck_pull {
    front = duck_layer(s=1)
    core = duck_layer(s=1, core=true)
    back = duck_layer(s=-1)

    RightOf(core, front, gap=8)
    AlignTop(core, front)
    RightOf(back, core, gap=8)
    AlignTop(back, core)

    # stacked front to back, the cord going up (+z)
    Place(front, position=(0, -1.5, 0), face="front", up="up")
    Place(core, position=(0, 1.5, 0), face="front", up="up")
    Place(back, position=(0, 1.5, 0), face="back", up="up")

    assert abs(front.bb.width - 60 mm) < 1.5 mm, "about 60 mm tail to beak"
    assert front.body.rx * 2 == 44 mm and front.body.ry * 2 == 28 mm, "body 44 x 28"
    assert front.head.diameter == 20 mm, "head 20 across"
    assert core.chan.c.width == 3 mm, "3 mm cord channel"
    assert core.knot.k.diameter == 8 mm, "8 mm knot pocket"
    assert core.chan.c.bb.top > core.head.bb.top, "the channel opens at the top of the head"
    assert distance(core.knot.k, core.body) >= 3 mm, "the pocket is walled in"
}
