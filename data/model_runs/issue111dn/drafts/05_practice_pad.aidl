# Request: a 12-inch drum practice pad from three discs of 6 mm birch ply, 300 mm across,
# screwed together with eight 4 mm wood screws on a 280 mm circle (the first at 22.5 deg, so
# none sits under the lettering). From the bottom: (1) the base, with an 8.5 mm centre hole
# for a stand's M8 thread and 3 mm pilot holes for the screws; (2) the middle disc, with a
# hex trap for an M8 nut (13 mm across flats) at the centre and 4.5 mm screw holes; (3) the
# top ring, with a 256 mm opening for a 254 mm (10-inch) gum-rubber pad (1 mm play all
# round), 4.5 mm screw holes countersunk for 9 mm heads, "PRACTICE PAD" engraved 8 mm high
# along the ring's middle over the top and "PARADIDDLE" readable along the bottom.

import "std/shapes.aidl"
import "std/fasteners.aidl"

thickness 6 mm

D = 300 mm
pcd = 280 mm
opening = 256 mm
ring_mid = (D / 2 + opening / 2) / 2

assembly pad {
    solid base {
        body = Circle(center=(0, 0), diameter=D)
        Fixed(body)
        hole stand { c = Circle(center=(0, 0), diameter=8.5) }
        pilots = bolt_circle(count=8, pcd=pcd, hole_d=3 mm, start=22.5 deg)
    }

    solid middle {
        body = Circle(center=(0, 0), diameter=D)
        Fixed(body)
        nut = nut_trap(size=8)
        screws = bolt_circle(count=8, pcd=pcd, hole_d=4.5 mm, start=22.5 deg)
    }

    solid ring {
        body = Circle(center=(0, 0), diameter=D)
        Fixed(body)
        hole well { c = Circle(center=(0, 0), diameter=opening) }
        screws = bolt_circle(count=8, pcd=pcd, hole_d=4.5 mm, start=22.5 deg)
        Countersink(screws, diameter=9 mm)
        drawing words {
            mid = Circle(center=(0, 0), radius=ring_mid, construction=true)
            top = Text("PRACTICE PAD", along=mid, size=8, valign="middle")
            bottom = Text("PARADIDDLE", along=mid, size=8, valign="middle", flip=true)
        }
    }

    # flat: side by side
    RightOf(middle, base, gap=5)
    RightOf(ring, middle, gap=5)
    AlignCenterY(middle, base)
    AlignCenterY(ring, base)

    # assembled: stacked, base at the bottom
    Place(base, position=(0, 0, 0), face="up")
    Place(middle, position=(0, 0, 6 mm), face="up")
    Place(ring, position=(0, 0, 12 mm), face="up")

    assert base.body.diameter == 300 mm
    assert ring.well.c.diameter - 254 mm == 2 mm, "1 mm play all round the rubber"
    assert middle.nut.hex.across_flats == 13 mm, "M8 nut, 13 mm across flats"
    assert len(ring.screws.bolt) == 8
    assert ring.screws.pitch.diameter == 280 mm
}
