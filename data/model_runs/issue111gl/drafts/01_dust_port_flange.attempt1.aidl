# Request: a 4-inch dust-collection port for the side of my router-table cabinet, cut
# from 6 mm birch ply. A 150 x 150 mm square flange (10 mm corner radius) with a 90 mm
# bore that the 100 mm hose butts against, and four holes for M4 flat-head screws
# (countersunk for 9 mm heads) 15 mm in from the corners. Glued on its face, a collar of
# two rings 130 mm across with a 102 mm bore, so the hose pushes 12 mm in. The outer ring
# is engraved "DUST 100 MM" over the top and "ROUTER TABLE" under the bottom, readable.

import "std/fasteners.aidl"

units mm
t = 6 mm
thickness t

flange_w = 150 mm
bore_d = 90 mm
ring_od = 130 mm
ring_id = 102 mm

def collar_ring(labelled=false) -> solid {
    disc = Circle(center=(0, 0), diameter=ring_od)
    hole bore { c = Circle(center=(0, 0), diameter=ring_id) }
    Concentric(bore.c, disc)
    if labelled {
        drawing label {
            path = Circle(center=(0, 0), radius=(ring_od + ring_id) / 4, construction=true)
            top = Text("DUST 100 MM", along=path, size=6, valign="middle")
            bottom = Text("ROUTER TABLE", along=path, size=6, valign="middle", flip=true)
        }
        Concentric(label.path, disc)
    }
}

assembly dust_port {
    solid flange {
        plate = RoundedRectangle(center=(0, 0), width=flange_w, height=flange_w, corner_radius=10)
        hole bore { c = Circle(center=(0, 0), diameter=bore_d) }
        Fixed(plate)
        Concentric(bore.c, plate.center)
        screw = clearance_hole(size=4)
        screws = CornerPattern(screw, plate, inset=15)
        Countersink(screws, diameter=9)

        assert plate.width == 150 mm and plate.height == 150 mm, "150 x 150 flange"
        assert bore.c.diameter == 90 mm, "the hose butts on a 90 mm bore"
        assert len(screws) == 4, "four screws"
        assert screws[0].c.center.x - plate.bb.left == 15 mm, "screws 15 mm in from the sides"
        assert screws[0].c.center.y - plate.bb.bottom == 15 mm, "screws 15 mm in from the bottom"
        assert screws[2].c.center.x - plate.center.x >= ring_od / 2 + 4.5 mm,
            "screw heads clear of the collar"
    }
    inner = collar_ring()
    outer = collar_ring(labelled=true)

    # flat on the sheet: side by side
    RightOf(inner, flange, gap=10)
    AlignCenterY(inner, flange)
    RightOf(outer, inner, gap=10)
    AlignCenterY(outer, inner)

    # assembled: the collar stacked on the flange's face
    Place(flange, position=(0, 0, 0))
    Place(inner, position=(0, 0, t))
    Place(outer, position=(0, 0, 2 * t))

    assert inner.disc.diameter == 130 mm and inner.bore.c.diameter == 102 mm, "collar ring 130 / 102"
    assert 2 * t == 12 mm, "the hose pushes 12 mm in"
}
