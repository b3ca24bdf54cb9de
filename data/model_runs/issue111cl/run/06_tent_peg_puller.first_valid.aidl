# Request: a tent peg puller for the camping box, from 6 mm birch ply. A rounded bar 160 mm long
# and 50 mm tall (round ends) with a hand hole 80 x 26 mm to grip it, a hook slot 7 mm wide cut
# up and back into the far end from the bottom edge (it catches the peg's head, then you pull),
# a 6 mm lanyard hole in the other end, "PULL" engraved under the hand hole, and every corner
# softened with a 1.5 mm round.

units mm
thickness 6 mm

param length = 160 mm, min = 130 mm, max = 200 mm
param height = 50 mm, min = 40 mm, max = 60 mm
param hook_w = 7 mm, min = 5 mm, max = 10 mm

solid peg_puller {
    end_l = Circle(center=(0, 0), diameter=height, construction=true)
    end_r = Circle(center=(length - height, 0), diameter=height, construction=true)
    bar = Hull(end_l, end_r)

    hole grip {
        s = Slot(center=(40, 4), length=80, width=26)
    }
    hole hook {
        s = Slot(start=(length - height + 14, -height / 2 - 7), end=(length - height - 2, 0),
                 width=hook_w)
    }
    hole lanyard {
        c = Circle(center=(-14, 0), diameter=6)
    }
    drawing label {
        t = Text("PULL", position=(40, -17), size=6, valign="middle")
    }
    Fillet(1.5)

    assert bar.bb.width == 160 mm and bar.bb.height == 50 mm, "160 x 50 bar"
    assert grip.s.length == 80 mm and grip.s.width == 26 mm, "80 x 26 hand hole"
    assert hook.s.width == 7 mm, "7 mm hook slot"
    assert lanyard.c.diameter == 6 mm, "6 mm lanyard hole"
}
