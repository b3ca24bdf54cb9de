# Request: a battle arena for spinning tops, from 6 mm ply: four 300 mm discs stacked and bolted
# with four M4 bolts (4.5 mm holes on a 280 mm circle, at 45, 135, 225 and 315 deg). The base is
# a full floor with a 40 mm and a 100 mm target circle engraved at its centre; above it three
# rings with bores of 170, 220 and 260 mm make a stepped bowl. The top ring has three pockets
# (40 mm wide, reaching out to 143 mm from the centre, at 90, 210 and 330 deg) that a top can be
# knocked into. On the lowest ring's visible step (between the 170 and 220 bores) engrave
# "BATTLE ARENA" over the top and "LET IT RIP!" under the bottom, 9 mm letters.

units mm
thickness 6 mm

import "std/shapes.aidl"

def layer(bore=0 mm, pockets=0) -> solid {
    body = Circle(center=(0, 0), diameter=300)
    bolts = bolt_circle(count=4, pcd=280 mm, hole_d=4.5 mm, start=45 deg)
    if bore > 0 mm {
        hole well {
            c = Circle(center=(0, 0), diameter=bore)
        }
    }
    if pockets > 0 {
        hole pocket {
            for k in range(pockets) {
                p = Rectangle(start=polar((0, 0), bore / 2 - 5 mm, 90 deg + k * 120 deg),
                              end=polar((0, 0), 143 mm, 90 deg + k * 120 deg), width=40)
            }
        }
        AllowOverlap(pocket, well)
    }
}

assembly arena {
    base = layer()
    r1 = layer(bore=170 mm)
    r2 = layer(bore=220 mm)
    r3 = layer(bore=260 mm, pockets=3)

    drawing target {
        inner = Circle(center=(0, 0), diameter=40)
        outer = Circle(center=(0, 0), diameter=100)
    }
    Concentric(target.inner, base.body)
    CutInto(target, base)

    drawing words {
        guide = Circle(center=(0, 0), radius=97.5, construction=true)
        title = Text("BATTLE ARENA", along=guide, size=9, valign="middle")
        motto = Text("LET IT RIP!", along=guide, size=9, valign="middle", flip=true)
    }
    Concentric(words.guide, r1.body)
    CutInto(words, r1)

    # flat for cutting: two by two, 10 mm apart
    RightOf(r1, base, gap=10)
    AlignTop(r1, base)
    Below(r2, base, gap=10)
    AlignLeft(r2, base)
    RightOf(r3, r2, gap=10)
    AlignTop(r3, r2)

    # assembled: stacked, centres on one axis
    Place(base, position=(0, 0, 0))
    Place(r1, position=(0, 0, 6 mm))
    Place(r2, position=(0, 0, 12 mm))
    Place(r3, position=(0, 0, 18 mm))

    assert base.body.diameter == 300 mm, "300 mm discs"
    assert r1.well.c.diameter == 170 mm and r2.well.c.diameter == 220 mm and
        r3.well.c.diameter == 260 mm, "bores 170, 220, 260"
    assert len(r3.pocket.p) == 3, "three pockets"
    assert r3.pocket.p[0].width == 40 mm, "pockets 40 wide"
    assert r3.body.bb.top - r3.pocket.bb.top >= 5 mm, "a 5 mm wall behind each pocket"
    assert len(base.bolts.bolt) == 4, "four bolts"
    assert distance(words, r1.well) >= 2 mm, "words clear of the 170 bore"
    assert words.bb.width <= 220 mm - 4 mm, "words inside the 220 bore above"
    assert target.outer.diameter == 100 mm and target.inner.diameter == 40 mm, "target 40 and 100"
}
