# Request (music): a guitar string winder from 3 mm acrylic, glued in layers. The crank
# arm is 95 mm from the cup's centre to the knob's axle, a 34 mm round head tapering to a
# 16 mm round end, with a 4.2 mm hole there for an M4 bolt that carries the knob, and a
# bridge-pin puller notch 3.5 mm wide cut 9 mm down through the arm's top edge, 60 mm from
# the head's centre. Two 34 mm cup rings glued on the head, each with a 20 x 7 mm slot
# (rounded ends) that fits over the tuning-peg button, make a 6 mm deep cup. The knob is
# three 20 mm discs with a 4.5 mm hole, knurled by eight 4 mm scallops round the rim,
# glued under the arm's end to spin on the bolt. "TUNE UP" engraved in 5 mm single-stroke
# letters along the arm.

thickness 3 mm

param reach = 95 mm, min = 70 mm, max = 140 mm
param head_d = 34 mm, min = 28 mm, max = 44 mm
param peg_len = 20 mm, min = 14 mm, max = 26 mm
param peg_w = 7 mm, min = 5 mm, max = 10 mm

# FIX after the first valid program: the puller notch was placed by a guessed y (5 mm),
# which left it 8.1 mm deep, not 9. The arm's top edge is the hull's tangent line from the
# head's circle to the end's; its height at x, so the notch is measured from it:
sa = (head_d / 2 - 8 mm) / reach
ca = sqrt(1 - sa ** 2)
def edge_y(x) = head_d / 2 * ca - sa * (x - head_d / 2 * sa) / ca

def cup() -> solid {
    ring = Circle(center=(0, 0), diameter=head_d)
    hole peg { s = Slot(center=(0, 0), length=peg_len, width=peg_w) }
}

def knob() -> solid {
    disc = Circle(center=(0, 0), diameter=20)
    hole bore { c = Circle(center=(0, 0), diameter=4.5) }
    hole knurl { c = Circle(center=(10, 0), diameter=4) }
    CircularPattern(knurl, 8, disc.center)
}

assembly winder {
    solid arm {
        body = Hull(Circle(center=(0, 0), diameter=head_d), Circle(center=(reach, 0), diameter=16))
        hole axle { c = Circle(center=(reach, 0), diameter=4.2) }
        hole puller { s = Slot(start=(60, edge_y(60 mm) + 3 mm), end=(60, edge_y(60 mm) - 9 mm + 1.75 mm), width=3.5) }
        drawing label { word = Text("TUNE UP", position=(42, -4), size=5, valign="middle") }
    }
    cup_a = cup()
    cup_b = cup()
    knob_a = knob()
    knob_b = knob()
    knob_c = knob()

    # flat on the sheet: the rings and knobs in a row under the arm
    Below(cup_a, arm, gap=5)
    AlignLeft(cup_a, arm)
    RightOf(cup_b, cup_a, gap=4)
    AlignBottom(cup_b, cup_a)
    RightOf(knob_a, cup_b, gap=4)
    AlignBottom(knob_a, cup_a)
    RightOf(knob_b, knob_a, gap=4)
    AlignBottom(knob_b, cup_a)
    RightOf(knob_c, knob_b, gap=4)
    AlignBottom(knob_c, cup_a)

    # assembled: the cup stacked on the head, the knob under the arm's end
    Place(arm, position=(0, 0, 0))
    Place(cup_a, position=(0, 0, 3))
    Place(cup_b, position=(0, 0, 6))
    Place(knob_a, position=(reach, 0, -3))
    Place(knob_b, position=(reach, 0, -6))
    Place(knob_c, position=(reach, 0, -9))

    assert arm.axle.c.center.x - arm.body.bb.left - head_d / 2 == 95 mm, "95 mm from the cup to the knob"
    assert arm.body.bb.height == 34 mm, "34 mm head"
    assert arm.body.bb.right - arm.axle.c.center.x == 8 mm, "16 mm round end"
    assert cup_a.peg.s.length == 20 mm and cup_a.peg.s.width == 7 mm, "20 x 7 peg slot"
    assert arm.puller.s.center.x - (arm.body.bb.left + head_d / 2) == 60 mm, "puller 60 mm from the head"
    assert knob_a.disc.diameter == 20 mm, "20 mm knob"
    assert edge_y(60 mm) - (arm.puller.s.end.y - arm.body.bb.center_y - 3.5 mm / 2) == 9 mm, "puller notch 9 mm deep"
}
