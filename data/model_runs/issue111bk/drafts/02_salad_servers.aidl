# Request: a pair of flat salad servers (a wedding present) cut from 6 mm bamboo ply: a spoon
# and a fork, each 280 mm overall, with an oval bowl 70 wide x 90 long and a handle 20 mm wide
# at the neck widening to 28 mm at its round end, the neck blended into the bowl with r8.
# A 6 mm hanging hole 14 mm from the handle's end. The fork's bowl has two 6 mm wide slots
# 40 mm deep from its tip, 24 mm apart, leaving three tines. The couple's initials "E & T"
# engraved along each handle, 8 mm tall, 140 mm from the bowl's tip.

thickness 6 mm

overall = 280 mm
bowl_w = 70 mm
bowl_l = 90 mm

def server(fork=false) -> solid {
    bowl = Ellipse(center=(0, 0), rx=bowl_w / 2, ry=bowl_l / 2)
    # the handle: a taper from the neck (inside the bowl's end) to the round end
    neck_y = -bowl_l / 2 + 5
    end_y = bowl_l / 2 - overall + 14
    grip = Trapezoid(center=(0, (neck_y + end_y) / 2), bottom_width=28, top_width=20,
                     height=neck_y - end_y)
    knob = Circle(center=(0, end_y), diameter=28)
    Fillet([bowl, grip], 8)
    hole hang {
        c = Circle(center=(0, bowl_l / 2 - overall + 14), diameter=6)
    }
    if fork {
        hole tines {
            for x in [-12, 12] {
                s = Slot(start=(x, bowl_l / 2 - 40 + 3), end=(x, bowl_l / 2 + 5), width=6)
            }
        }
    }
    drawing initials {
        t = Text("E & T", position=(0, bowl_l / 2 - 140), size=8, rotation=90,
                 valign="middle")
    }
}

assembly salad_servers {
    spoon = server()
    fork = server(fork=true)
    RightOf(fork, spoon, gap=10)
    AlignBottom(fork, spoon)

    assert spoon.bowl.bb.top - spoon.knob.bb.bottom == 280 mm, "spoon 280 overall"
    assert fork.bowl.bb.top - fork.knob.bb.bottom == 280 mm, "fork 280 overall"
    assert spoon.bowl.bb.width == 70 mm and spoon.bowl.bb.height == 90 mm, "bowl 70 x 90"
    assert spoon.hang.c.center.y - spoon.knob.bb.bottom == 14 mm, "hole 14 from the end"
    assert fork.bowl.bb.top - fork.tines.bb.bottom == 40 mm, "tines 40 deep"
    assert fork.tines.s[1].start.x - fork.tines.s[0].start.x == 24 mm, "slots 24 apart"
    assert spoon.bowl.bb.top - spoon.initials.t.position.y == 140 mm, "initials 140 from the tip"
}
