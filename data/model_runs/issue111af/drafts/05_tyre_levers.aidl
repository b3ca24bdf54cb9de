# Request (sport / cycling): a set of 3 bicycle tyre levers cut from 5 mm Delrin. Each lever is
# 115 mm long overall: a round handle end 20 mm across tapering to a 12 mm round tip; under
# the tip a small barb (hook) 4 mm deep to catch the tyre bead; near the handle a 3.5 mm wide
# spoke-hook notch cut slanting into the top edge; a 5 mm hole for a key ring; "TYRE LEVER"
# engraved along the shaft and the lever's number (1-3) engraved near the tip.
# All outside corners rounded 0.8 mm so the levers don't cut the tube.

units mm
thickness 5 mm

param length = 115 mm, min = 90 mm, max = 160 mm
handle_d = 20 mm
tip_d = 12 mm
count = 3

def lever(n=1) -> solid {
    shaft = Hull(Circle(center=(0, 0), diameter=handle_d),
                 Circle(center=(length - handle_d / 2 - tip_d / 2, 0), diameter=tip_d))
    barb = Polygon([(length - 24, -3), (length - 13, -5.5), (length - 20, -10)])
    hole ring { c = Circle(center=(-2, 0), diameter=5) }
    hole spoke { s = Slot(start=(9, 3), end=(17, 14), width=3.5) }
    drawing words {
        name = Text("TYRE LEVER", position=(40, 0), size=3.5, valign="middle")
        num = Text(str(n), position=(length - 25, 0), size=4, valign="middle")
    }
    Fillet(0.8)
}

assembly tyre_levers {
    l1 = lever(n=1)
    l2 = lever(n=2)
    l3 = lever(n=3)
    Below(l2, l1, gap=4)
    Below(l3, l2, gap=4)
    AlignLeft(l2, l1)
    AlignLeft(l3, l1)

    assert l1.shaft.bb.width == 115 mm, "115 mm long"
    assert l1.shaft.bb.height == 20 mm, "handle 20 across"
    assert abs(l1.shaft.center.y - 12 mm / 2 - l1.barb.bb.bottom - 4 mm) < 0.01 mm, "barb 4 deep under the tip"
    assert l1.ring.c.diameter == 5 mm, "key ring hole 5"
    assert l1.spoke.s.width == 3.5 mm, "spoke notch 3.5 wide"
}
