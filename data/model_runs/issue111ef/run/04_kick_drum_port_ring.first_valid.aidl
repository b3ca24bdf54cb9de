# Request (music): a port for the resonant (front) head of a 22" bass drum, 3 mm acrylic.
# - The port is a 127 mm (5") hole in the head; two rings clamp the head round it, both
#   180 mm outside and 127 mm inside.
# - Six M3 flat-head screws on a 144 mm circle, the first at 3 o'clock (3.4 mm holes).
#   The outer ring's holes countersunk for 6.5 mm heads; the inner ring holds the M3 nuts
#   in hex traps (5.5 mm across flats).
# - The outer ring engraved with the band's name THE LOW END over the top (reading left to
#   right) and EST 2019 under the bottom (readable), 6 mm letters between radius 79 and 85.
# - In 3D: the outer ring in front of the head, the inner ring behind it.

import "std/shapes.aidl"
import "std/fasteners.aidl"
import "std/plates.aidl"

thickness 3 mm

assembly port {
    solid outer_ring {
        body = Circle(center=(0, 0), diameter=180)
        hole port_hole { c = Circle(center=(0, 0), diameter=127) }
        screws = bolt_circle(count=6, pcd=144 mm, hole_d=3.4 mm, start=0 deg)
        Countersink(screws, diameter=6.5 mm)
        name = text_on_arc(text="THE LOW END", radius=79 mm, size=6 mm, angle=90 deg)
        drawing since {
            ring = Circle(center=(0, 0), radius=85, construction=true)
            t = Text("EST 2019", along=ring, size=6, flip=true)
        }
    }

    solid inner_ring {
        body = Circle(center=(0, 0), diameter=180)
        hole port_hole { c = Circle(center=(0, 0), diameter=127) }
        for i in range(6) {
            nut = nut_trap(size=3, rotation=i * 60 deg, cx=72 mm * cos(i * 60 deg),
                           cy=72 mm * sin(i * 60 deg))
        }
    }

    RightOf(inner_ring, outer_ring, gap=10)
    AlignCenterY(inner_ring, outer_ring)

    # in 3D: the head at y = 0, the outer ring in front of it, the inner ring behind
    Place(outer_ring, position=(0, 0, 0), face="front", up="up")
    Place(inner_ring, position=(0, 3, 0), face="front", up="up")

    assert outer_ring.body.diameter == 180 mm and outer_ring.port_hole.c.diameter == 127 mm,
        "rings 180 outside, 127 inside"
    assert inner_ring.body.diameter == 180 mm and inner_ring.port_hole.c.diameter == 127 mm,
        "inner ring the same"
    assert len(outer_ring.screws.bolt) == 6 and len(inner_ring.nut) == 6, "six screws"
    assert outer_ring.screws.pitch.diameter == 144 mm, "on a 144 mm circle"
    assert outer_ring.screws.bolt[0].center.x - outer_ring.body.center.x == 72 mm,
        "the first at 3 o'clock"
    assert inner_ring.nut[0].hex.across_flats == 5.5 mm, "M3 nut traps"
    assert outer_ring.name.bb.top - outer_ring.body.center.y <= 85.5 mm, "name within r 85"
}
