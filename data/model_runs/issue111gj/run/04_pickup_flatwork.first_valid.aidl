# Request: flatwork for a hand-wound Strat-style single-coil guitar pickup, cut from 1.6 mm
# vulcanised fibre. Two plates, each a 70 x 17.5 mm stadium (round ends), with six 4.85 mm holes
# for the 5 mm Alnico pole magnets (press fit), 10.4 mm apart in a row along the middle, and two
# 2.8 mm mounting-screw holes 62 mm apart on the long axis. The bottom plate also has two 2.4 mm
# eyelet holes for the lead wires, 10.4 mm apart, centred between the middle poles and 6 mm off
# the axis, and "RWRP N" engraved on its outside face. Assembled: the coil space between the
# plates is 15 mm (the magnets stand 18.2 mm: both plates plus the coil).

units mm
thickness 1.6 mm

def flatwork(bottom=false) -> solid {
    body = Slot(center=(0, 0), length=70, width=17.5)
    hole pole {
        c = Circle(center=(-26, 0), diameter=4.85)
    }
    poles = LinearPattern(pole, 6, (10.4, 0))
    hole screws {
        a = Circle(center=(-31, 0), diameter=2.8)
        b = Circle(center=(31, 0), diameter=2.8)
    }
    if bottom {
        hole eyelets {
            e1 = Circle(center=(-5.2, -6), diameter=2.4)
            e2 = Circle(center=(5.2, -6), diameter=2.4)
        }
        drawing mark {
            t = Text("RWRP N", position=(0, 5.6), size=3, valign="middle")
        }
    }
}

assembly pickup {
    top = flatwork()
    bottom = flatwork(bottom=true)

    Below(bottom, top, gap=4)
    AlignLeft(bottom, top)

    # bottom plate's marked face looks down, out of the pickup; the top plate 15 mm above it
    Place(bottom, position=(0, 0, 1.6 mm), face="down")
    Place(top, position=(0, 0, 1.6 mm + 15 mm))

    assert top.body.bb.width == 70 mm and top.body.bb.height == 17.5 mm, "70 x 17.5 plates"
    assert len(top.poles) == 6, "six poles"
    assert top.poles[5].c.center.x - top.poles[0].c.center.x == 5 * 10.4 mm, "10.4 mm pole pitch"
    assert top.pole.c.diameter == 4.85 mm, "4.85 mm pole holes"
    assert top.screws.b.center.x - top.screws.a.center.x == 62 mm, "screws 62 apart"
    assert bottom.eyelets.e2.center.x - bottom.eyelets.e1.center.x == 10.4 mm, "eyelets 10.4 apart"
    assert abs((bottom.eyelets.e1.center.x + bottom.eyelets.e2.center.x) / 2 -
               (bottom.poles[2].c.center.x + bottom.poles[3].c.center.x) / 2) < 0.01 mm,
        "eyelets centred between the middle poles"
    assert bottom.body.center.y - bottom.eyelets.e1.center.y == 6 mm, "eyelets 6 off the axis"
    assert distance(bottom.eyelets, bottom.poles) >= 1 mm, "eyelets clear of the poles"
    assert distance(bottom.mark, bottom.poles) >= 0.5 mm, "mark clear of the poles"
}
