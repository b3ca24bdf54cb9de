# Request (office): a slim pen drawer to screw under my desk top, 3 mm ply.
# Carcass outside 260 mm wide, 220 mm deep, 50 mm high, with a finger-jointed drawer
# in it (the template's round finger pull in the front). The carcass top is screwed
# up into the desk with 4 pan-head 4 mm wood screws: 4.5 mm holes 20 mm in from the
# sides and 20 mm in from the front and back of the top panel. "PENS" engraved 8 mm
# high on the drawer front left of the pull and "CLIPS" right of it, each 40 mm from
# the pull's centre.

units mm
thickness 3 mm

import "std/boxes.aidl"

L = 260 mm
D = 220 mm
H = 50 mm
inset = 20 mm

assembly desk_drawer {
    k = drawer(length=L, depth=D, height=H, thickness=3 mm)

    hole screws {
        for i in range(2) {
            for j in range(2) {
                c = Circle(center=((i - 0.5) * (L - 2 * inset), (j - 0.5) * (D - 2 * inset)),
                           diameter=4.5 mm)
            }
        }
    }
    CenterInside(screws, k.carcass.top)
    CutInto(screws, k.carcass.top)

    drawing label {
        pens = Text("PENS", position=(-40, 0), size=8, valign="middle")
        clips = Text("CLIPS", position=(40, 0), size=8, valign="middle")
    }
    At(label.pens.position, k.box.front.pull.p.center, dx=-40 mm)
    CutInto(label, k.box.front)

    assert screws.c[1][0].center.x - screws.c[0][0].center.x == 220 mm, "260 - 2 x 20 apart"
    assert screws.c[0][1].center.y - screws.c[0][0].center.y == 180 mm, "220 - 2 x 20 apart"
    assert screws.c[0][0].center.x - k.carcass.top.bb.left == 20 mm, "20 mm in from the side"
    assert distance(label.pens, k.box.front.pull) >= 3 mm, "label clear of the pull"
    assert distance(label.clips, k.box.front.pull) >= 3 mm, "label clear of the pull"
}
