# Request: a lid for opened 400 g cat-food tins (the tin's rim is 73 mm across inside),
# from 3 mm acrylic, two layers glued together. The top disc is 84 mm across with a pull
# tab sticking out 20 mm past its rim, 14 mm wide with a round end, a 6 mm hole in the
# end to hang the lid on a hook, the tab's joins to the disc rounded R3. On the top a
# paw print (a pad and four toes) is engraved filled in the middle and the cat's name
# "MILO" (bold, 7 mm capitals) along the rim over the top. Under it a plug ring 72.5 mm
# across and 60 mm inside sits in the tin's rim and seals it.

import "std/shapes.aidl"

units mm
thickness 3 mm
kerf 0.1 mm

rim_inside = 73 mm

assembly cat_food_lid {
    solid top {
        disc = Circle(center=(0, 0), diameter=84)
        tab = Slot(center=(47.5, 0), length=29, width=14)
        hole hang {
            c = Circle(center=(55, 0), diameter=6)
        }
        Fillet([disc, tab], 3)
        drawing paw {
            pad = Ellipse(center=(0, -8), rx=11, ry=9, fill=true)
            toe1 = Circle(center=(-13, 4), radius=4.5, fill=true)
            toe2 = Circle(center=(-5, 10), radius=4.5, fill=true)
            toe3 = Circle(center=(5, 10), radius=4.5, fill=true)
            toe4 = Circle(center=(13, 4), radius=4.5, fill=true)
        }
        drawing name {
            ring = Circle(center=(0, 0), radius=30, construction=true)
            word = Text("MILO", along=ring, size=7, font="sans:Bold")
        }
        Fixed(disc)

        assert disc.diameter == 84 mm, "top disc 84 mm"
        assert tab.bb.right - disc.bb.right == 20 mm, "tab sticks out 20 mm"
        assert tab.width == 14 mm, "tab 14 mm wide"
        assert hang.c.diameter == 6 mm, "6 mm hanging hole"
        assert tab.bb.right - hang.c.center.x == 7 mm, "hole centred in the tab's round end"
        assert distance(name, paw) >= 3 mm, "name clear of the paw"
        assert distance(name, disc.center) + 0 mm <= 42 mm, "name on the disc"
        assert ring.radius + word.size <= disc.radius - 3 mm, "name inside the rim"
    }
    plug = washer(outer=72.5 mm, inner=60 mm)
    RightOf(plug, top, gap=6)
    AlignCenterY(plug, top)

    assert plug.outer == 72.5 mm and plug.inner == 60 mm, "plug ring 72.5 / 60"
    assert plug.outer < rim_inside, "the plug goes into the tin"

    # 3D: the plug ring under the disc, concentric
    Place(plug, position=(0, 0, 0))
    Place(top, position=(0, 0, 3))
}
