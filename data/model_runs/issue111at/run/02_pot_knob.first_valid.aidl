# Request (electronics): a stacked knob for a 6 mm D-shaft potentiometer (flat leaves 4.5 mm),
# from four layers of 3 mm black acrylic glued together: a 30 mm skirt at the bottom with an
# engraved pointer line at 12 o'clock running in from 0.8 mm to 4 mm from its rim, two 22 mm
# grip layers each with 12 round scallops (2.5 mm radius, centres 0.5 mm outside the rim) for
# the fingers, and a plain 22 mm cap on top with the same pointer line. The skirt and both grips
# have a D-bore 6.1 mm across, flat 4.6 mm from the round side, flat toward the pointer; the
# cap is closed. Layers laid out in a row, 3 mm apart, for cutting.

thickness 3 mm

param shaft = 6.1 mm, min = 6 mm, max = 6.4 mm   # bore across the round
param flat = 4.6 mm, min = 4.4 mm, max = 5 mm    # round side to the flat

def layer(d, bore=true, scallops=0, pointer=false) -> solid {
    disc = Circle(center=(0, 0), diameter=d)
    if bore {
        hole dbore {
            k = Intersect(Circle(center=(0, 0), diameter=shaft),
                          Rectangle(bottom_left=(-shaft / 2, -shaft / 2), width=shaft, height=flat))
        }
    }
    if scallops > 0 {
        hole notch {
            c = Circle(center=(d / 2 + 0.5, 0), radius=2.5)
        }
        ring = CircularPattern(notch, scallops, disc.center)
        assert len(ring) == 12, "12 scallops"
    }
    if pointer {
        drawing mark {
            l = Line((0, d / 2 - 4), (0, d / 2 - 0.8))
        }
    }
}

assembly knob {
    skirt = layer(30 mm, pointer=true)
    grip1 = layer(22 mm, scallops=12)
    grip2 = layer(22 mm, scallops=12)
    cap = layer(22 mm, bore=false, pointer=true)
    RightOf(grip1, skirt, gap=3)
    RightOf(grip2, grip1, gap=3)
    RightOf(cap, grip2, gap=3)
    AlignCenterY(grip1, skirt)
    AlignCenterY(grip2, skirt)
    AlignCenterY(cap, skirt)

    assert skirt.disc.diameter == 30 mm, "skirt 30"
    assert grip1.disc.diameter == 22 mm and grip2.disc.diameter == 22 mm, "grips 22"
    assert cap.disc.diameter == 22 mm, "cap 22"
    assert abs(skirt.dbore.bb.width - 6.1 mm) < 0.01 mm, "bore 6.1 across"
    assert abs(skirt.dbore.bb.height - 4.6 mm) < 0.01 mm, "flat 4.6 from the round side"
    assert skirt.dbore.bb.top > skirt.disc.center.y, "flat toward the pointer (up)"
    assert abs(skirt.disc.bb.top - skirt.mark.l.end.y - 0.8 mm) < 0.01 mm, "pointer 0.8 from the rim"
    assert abs(skirt.mark.l.length - 3.2 mm) < 0.01 mm, "pointer from 0.8 to 4 mm in"
}
