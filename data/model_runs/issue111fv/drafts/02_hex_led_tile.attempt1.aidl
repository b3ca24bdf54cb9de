# Request: a hexagonal LED wall tile (one of a set, Nanoleaf style) for a WS2812 strip stuck
# round the inside of its wall. Three layers, each a hexagon 150 mm across flats (flats at top
# and bottom), held by six M3 screws (3.4 mm holes) on a 160 mm circle through the corners:
# - base, 3 mm plywood: a keyhole (8 mm head, 4 mm slot 10 mm long, pointing up) 40 mm above the
#   centre to hang it; "DATA IN" engraved by the top wire notch, "DATA OUT" by the bottom one
#   (4 mm letters);
# - spacer ring, 6 mm plywood: a wall 12 mm wide (opening 126 mm across flats) with a 10 mm wire
#   notch through the wall in the middle of the top and of the bottom flat;
# - diffuser, 3 mm opal acrylic: three concentric hexagons engraved, 40, 80 and 120 mm across flats.

import "std/shapes.aidl"
import "std/plates.aidl"

thickness 3 mm

AF = 150 mm
WALL = 12 mm
PCD = 160 mm

assembly tile {
    solid base {
        plate = RegularPolygon(center=(0, 0), across_flats=AF, sides=6)
        screws = bolt_circle(count=6, pcd=PCD, hole_d=3.4 mm, start=0 deg)
        hang = keyhole(head=8 mm, slot_width=4 mm, length=10 mm, direction=90 deg,
                       cx=0 mm, cy=40 mm)
        drawing marks {
            din = Text("DATA IN", position=(0, AF / 2 - WALL - 8 mm), size=4 mm, valign="middle")
            dout = Text("DATA OUT", position=(0, -AF / 2 + WALL + 8 mm), size=4 mm, valign="middle")
        }
    }

    solid ring {
        thickness 6 mm
        body = RegularPolygon(center=(0, 0), across_flats=AF, sides=6)
        hole opening {
            h = RegularPolygon(center=(0, 0), across_flats=AF - 2 * WALL, sides=6)
        }
        hole notches {
            top = Rectangle(center=(0, AF / 2 - WALL / 2), width=10 mm, height=WALL + 2 mm)
            bottom = Rectangle(center=(0, -AF / 2 + WALL / 2), width=10 mm, height=WALL + 2 mm)
        }
        screws = bolt_circle(count=6, pcd=PCD, hole_d=3.4 mm, start=0 deg)
    }

    solid diffuser {
        plate = RegularPolygon(center=(0, 0), across_flats=AF, sides=6)
        screws = bolt_circle(count=6, pcd=PCD, hole_d=3.4 mm, start=0 deg)
        drawing rings {
            for i in range(3) {
                h = RegularPolygon(center=(0, 0), across_flats=40 mm * (i + 1), sides=6)
            }
        }
    }

    # flat on the sheet: side by side
    RightOf(ring, base, gap=10 mm)
    AlignTop(ring, base)
    RightOf(diffuser, ring, gap=10 mm)
    AlignTop(diffuser, ring)

    # in 3D: stacked
    Place(base, position=(0, 0, 0))
    Place(ring, position=(0, 0, 3 mm))
    Place(diffuser, position=(0, 0, 9 mm))

    assert base.plate.across_flats == 150 mm and ring.body.across_flats == 150 mm and
        diffuser.plate.across_flats == 150 mm, "all three 150 across flats"
    assert (ring.body.across_flats - ring.opening.h.across_flats) / 2 == 12 mm, "wall 12 mm"
    assert ring.opening.h.across_flats == 126 mm, "opening 126 across flats"
    assert len(base.screws.bolt) == 6 and len(ring.screws.bolt) == 6 and
        len(diffuser.screws.bolt) == 6, "six screws"
    assert distance(base.screws.bolt[0].center, base.plate.center) == 80 mm, "on a 160 circle"
    assert base.screws.bolt[0].diameter == 3.4 mm, "M3 clearance"
    assert ring.notches.top.bb.width == 10 mm and ring.notches.bottom.bb.width == 10 mm,
        "10 mm notches"
    assert base.hang.head_hole.center.y - base.plate.center.y == 40 mm, "keyhole 40 above centre"
    assert diffuser.rings.h[0].across_flats == 40 mm and diffuser.rings.h[2].across_flats == 120 mm,
        "engraved hexagons 40 and 120"
    assert distance(ring.screws, ring.opening) >= 3 mm, "screw holes clear of the opening"
    assert distance(base.marks, base.hang) >= 3 mm, "labels clear of the keyhole"
    # the holes line up through the stack
    for i in range(6) {
        assert base.screws.bolt[i].center.x - base.plate.center.x ==
            ring.screws.bolt[i].center.x - ring.body.center.x, "holes line up"
    }
}
