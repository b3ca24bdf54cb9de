# Request: a lotus tealight holder for Diwali, four layers of 4 mm birch ply glued in a stack.
# Each layer is a lotus: 8 pointed petals (each a lens, pointed at both ends) round a centre
# disc, every petal with an engraved vein down its middle. Layer 1 (bottom, solid, no hole):
# petals 48 mm long, 26 mm wide, tips 120 mm across, one petal pointing straight up, centre
# disc 60 mm. Layer 2: the same size turned 22.5 deg so its petals sit between layer 1's, with a
# 40 mm hole for the tealight cup (38 mm). Layer 3: petals 36 x 22 mm, tips 96 mm across,
# centre disc 52 mm, 40 mm hole, lined up with layer 1. Layer 4: petals 22 x 16 mm, tips 76 mm
# across, centre disc 48 mm, 40 mm hole, turned 22.5 deg. The well is 12 mm deep.

thickness 4 mm

# a lens petal of length plen and width pw: two circles of radius lens_r, their centres
# lens_off either side of the petal's axis
def lens_r(plen, pw) = (plen * plen / 4 + pw * pw / 4) / pw
def lens_off(plen, pw) = lens_r(plen, pw) - pw / 2

def lotus(ro=60 mm, plen=48 mm, pw=26 mm, rot=90 deg, disc_d=60 mm, hole_d=0 mm) -> solid {
    centre = Circle(center=(0, 0), diameter=disc_d)
    solid petal {
        k = Intersect(
            Circle(center=((ro - plen / 2) * cos(rot) - lens_off(plen, pw) * sin(rot),
                           (ro - plen / 2) * sin(rot) + lens_off(plen, pw) * cos(rot)),
                   radius=lens_r(plen, pw)),
            Circle(center=((ro - plen / 2) * cos(rot) + lens_off(plen, pw) * sin(rot),
                           (ro - plen / 2) * sin(rot) - lens_off(plen, pw) * cos(rot)),
                   radius=lens_r(plen, pw)))
    }
    petals = CircularPattern(petal, 8, (0, 0))
    # FIX after the first valid program: the veins of layers 3 and 4 started in (or 0.4 mm
    # from) the well (W0505, W0516): start each vein 2 mm clear of the well
    drawing vein {
        v = Line((max(ro - 0.8 * plen, hole_d / 2 + 2 mm) * cos(rot),
                  max(ro - 0.8 * plen, hole_d / 2 + 2 mm) * sin(rot)),
                 ((ro - 5 mm) * cos(rot), (ro - 5 mm) * sin(rot)))
    }
    veins = CircularPattern(vein, 8, (0, 0))
    if hole_d > 0 mm {
        hole well { c = Circle(center=(0, 0), diameter=hole_d) }
    }
}

assembly diya {
    layer1 = lotus(ro=60 mm, plen=48 mm, pw=26 mm, rot=90 deg, disc_d=60 mm)
    layer2 = lotus(ro=60 mm, plen=48 mm, pw=26 mm, rot=112.5 deg, disc_d=60 mm, hole_d=40 mm)
    layer3 = lotus(ro=48 mm, plen=36 mm, pw=22 mm, rot=90 deg, disc_d=52 mm, hole_d=40 mm)
    layer4 = lotus(ro=38 mm, plen=22 mm, pw=16 mm, rot=112.5 deg, disc_d=48 mm, hole_d=40 mm)

    # flat for cutting
    Fixed(layer1)
    RightOf(layer2, layer1, gap=6 mm)
    RightOf(layer3, layer2, gap=6 mm)
    RightOf(layer4, layer3, gap=6 mm)
    AlignCenterY(layer2, layer1)
    AlignCenterY(layer3, layer1)
    AlignCenterY(layer4, layer1)

    # glued up
    Place(layer1, position=(0, 0, 0))
    Place(layer2, position=(0, 0, 4 mm))
    Place(layer3, position=(0, 0, 8 mm))
    Place(layer4, position=(0, 0, 12 mm))

    assert len(layer1.petals) == 8, "8 petals"
    assert layer1.bb.height == 120 mm, "layer 1 tips 120 mm across"
    assert layer3.bb.height == 96 mm, "layer 3 tips 96 mm across"
    assert layer2.well.c.diameter == 40 mm, "40 mm well"
    assert 3 * 4 mm == 12 mm, "well 12 mm deep: three holed layers of 4 mm"
}
