# Request: a hexagonal LED wall tile (one of a set, Nanoleaf style) for a WS2812 strip stuck
# round the inside of its wall. Three layers, each a hexagon 150 mm across flats (flats at top
# and bottom), held by six M3 screws (3.4 mm holes) on a 160 mm circle through the corners:
# - base, 3 mm plywood: a keyhole (8 mm head, 4 mm slot 10 mm long, pointing up) 30 mm above the
#   centre to hang it; an 8 mm wire hole 55 mm above and one 55 mm below the centre, inside the
#   ring, "DATA IN" engraved right of the top one, "DATA OUT" right of the bottom one (4 mm letters);
# - spacer ring, 6 mm plywood: an unbroken wall 12 mm wide (opening 126 mm across flats);
# (changed after attempt 1: wire notches through the wall cut the ring in two (W0504), and the
#  labels touched the keyhole: the wires now leave through the base)
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
                       cx=0 mm, cy=30 mm)
        hole wires {
            w_in = Circle(center=(0, 55 mm), diameter=8 mm)
            w_out = Circle(center=(0, -55 mm), diameter=8 mm)
        }
        drawing marks {
            din = Text("DATA IN", position=(7 mm, 55 mm), size=4 mm, anchor="start", valign="middle")
            dout = Text("DATA OUT", position=(7 mm, -55 mm), size=4 mm, anchor="start",
                        valign="middle")
        }
    }

    solid ring {
        thickness 6 mm
        body = RegularPolygon(center=(0, 0), across_flats=AF, sides=6)
        hole opening {
            h = RegularPolygon(center=(0, 0), across_flats=AF - 2 * WALL, sides=6)
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
    assert base.wires.w_in.diameter == 8 mm and base.wires.w_out.diameter == 8 mm, "8 mm wire holes"
    assert base.wires.w_in.center.y - base.plate.center.y == 55 mm and
        base.plate.center.y - base.wires.w_out.center.y == 55 mm, "wire holes 55 from the centre"
    assert base.hang.head_hole.center.y - base.plate.center.y == 30 mm, "keyhole 30 above centre"
    assert distance(base.wires, base.hang) >= 3 mm, "wire hole clear of the keyhole"
    assert distance(base.marks, base.wires) >= 1 mm, "labels clear of the wire holes"
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
