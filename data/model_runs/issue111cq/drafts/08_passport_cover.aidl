# Request: a wooden passport cover as a gift, 2 mm birch ply, one piece folded on a living
# hinge. Closed it is 130 tall x 95 wide per cover (a passport is 125 x 88 mm); the blank is
# two 95 mm halves with a 20 mm living-hinge spine between them (210 x 130 flat), corners R6.
# Hinge: cuts 15 mm long, 3 mm bridges, columns 2 mm apart, open at the top and bottom edges.
# Outside of the front cover (the right half, seen from outside): an 8-point compass rose
# (outer radius 22, inner 6) engraved filled with a 16 mm-radius ring, centred 20 mm above
# the half's middle; "PASSPORT" in a bold serif 10 mm filled, 22 mm below the middle; the name
# "AMELIA" in sans 6 mm, 45 mm below the middle. Inside the back cover (the left half): two
# vertical elastic straps hold the passport's back cover; each passes through two slits 12 x
# 1.6 mm, 6 mm in from the top and bottom edges, the straps 15 mm in from the half's sides.

import "std/plates.aidl"

units mm
thickness 2 mm

t = 2 mm
half_w = 95 mm
spine = 20 mm
h = 130 mm
front_x = spine / 2 + half_w / 2
back_x = -front_x

assembly passport_cover {
    solid cover {
        body = RoundedRectangle(center=(0, 0), width=2 * half_w + spine, height=h, corner_radius=6)
        hinge = living_hinge(width=spine, height=h, pitch=2 mm, cut=15 mm, bridge=3 mm,
                             cx=0 mm, cy=0 mm)
        hole straps {
            for sx in [-1, 1] {
                for sy in [-1, 1] {
                    s = Rectangle(center=(back_x + sx * (half_w / 2 - 15), sy * (h / 2 - 6)),
                                  width=12, height=1.6)
                }
            }
        }
        drawing art {
            rose = Star(center=(front_x, 20), points=8, outer_radius=22, inner_radius=6,
                        fill=true)
            ring = Circle(center=(front_x, 20), radius=16)
            title = Text("PASSPORT", position=(front_x, -22), size=10, font="serif:Bold",
                         valign="middle", fill=true)
            name = Text("AMELIA", position=(front_x, -45), size=6, font="sans",
                        valign="middle")
        }
    }
    # closed in the assembled view: the spine bent 180 deg, the engraved face outside
    Bend(cover, at=0, angle=-180 deg, radius=spine / pi - t / 2)

    # the request's numbers
    assert cover.body.bb.width == 210 mm and cover.body.bb.height == 130 mm, "blank 210 x 130"
    assert half_w >= 88 mm + 5 mm and h >= 125 mm + 5 mm, "a passport fits"
    assert sum([len(r) for r in cover.straps.s]) == 4, "4 slits"
    assert cover.art.rose.center.y == 20 mm, "rose 20 above the middle"
}
