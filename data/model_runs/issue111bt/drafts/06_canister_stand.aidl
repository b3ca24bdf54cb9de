# Request: a camping stove stand that keeps a 230 g screw-on gas canister (110 mm across) from
# tipping, two layers of 4 mm plywood glued together. Both layers share one footprint: a 130 mm
# disc with three 25 mm wide legs with round ends, at 90, 210 and 330 deg, their end arcs
# centred 120 mm from the centre, the legs blended into the disc with 10 mm fillets, and a 6 mm
# tent-peg hole at the centre of each leg's end. The base layer has a 60 mm hole in the middle
# (lighter, lets water out); the top layer has a 111 mm hole the canister stands in, with
# "GAS 230 g" engraved round the top of the ring and "KEEP LEVEL" round the bottom (5 mm).

units mm
thickness 4 mm

LEG_R = 120 mm
LEG_W = 25 mm
DISC_D = 130 mm
PEG_D = 6 mm
LEG_ANGLES = [90 deg, 210 deg, 330 deg]

def footprint(bore=60 mm) -> solid {
    disc = Circle(center=(0, 0), diameter=DISC_D)
    for k in range(3) {
        leg = Slot(start=(0, 0), end=(LEG_R * cos(LEG_ANGLES[k]), LEG_R * sin(LEG_ANGLES[k])),
                   width=LEG_W)
        hole peg {
            c = Circle(center=(LEG_R * cos(LEG_ANGLES[k]), LEG_R * sin(LEG_ANGLES[k])),
                       diameter=PEG_D)
        }
    }
    hole middle { c = Circle(center=(0, 0), diameter=bore) }
    Fillet([[leg[k], disc] for k in range(3)], 10)
}

assembly stand {
    base = footprint(bore=60 mm)
    top = footprint(bore=111 mm)
    drawing label {
        upper = Circle(center=(0, 0), radius=58, construction=true)
        lower = Circle(center=(0, 0), radius=63, construction=true)
        t1 = Text("GAS 230 g", along=upper, size=5)
        t2 = Text("KEEP LEVEL", along=lower, size=5, flip=true)
    }
    CenterInside(label, top.middle)
    CutInto(label, top)

    RightOf(top, base, gap=10)
    AlignCenterY(top, base)
    Place(base, position=(0, 0, 0))
    Place(top, position=(0, 0, 4))

    assert top.middle.c.diameter == 111 mm and base.middle.c.diameter == 60 mm, "bores"
    assert top.disc.diameter == 130 mm, "130 mm disc"
    assert distance(top.peg[0].c.center, top.disc.center) == 120 mm, "legs' ends 120 mm out"
    assert top.leg[0].width == 25 mm and top.peg[0].c.diameter == 6 mm, "25 mm legs, 6 mm pegs"
    assert len(top.leg) == 3, "three legs"
    # the ring left round the canister and the engraving on it
    assert (top.disc.diameter - top.middle.c.diameter) / 2 >= 9 mm, "ring at least 9 mm wide"
    assert label.lower.radius + 0.5 mm <= top.disc.radius and
        label.upper.radius - 1 mm >= top.middle.c.radius, "text on the ring"
}
