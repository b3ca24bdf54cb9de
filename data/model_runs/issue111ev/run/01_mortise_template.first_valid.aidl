# Request: a loose-tenon mortise template for my plunge router, cut from 6 mm MDF.
# The router runs a 17 mm (outside diameter) guide bushing and an 8 mm straight bit,
# to cut mortises for 8 x 40 mm floating tenons in 19 mm stock.
# - Template plate 220 x 140 mm, corners R6.
# - Guide slot: 17.3 mm wide (bushing + 0.3 mm play) and long enough that the bit cuts a
#   40 mm mortise: 40 - 8 + 17.3 = 49.3 mm end to end, centred left to right.
# - A fence strip 220 x 25 mm screwed under the plate along its front (bottom) edge; the
#   slot's centre sits 9.5 mm (half of 19 mm stock) in from the fence's inside edge.
# - Four M4 countersunk screws (8 mm heads) through the plate into the fence, 30 mm and
#   90 mm either side of the centre, on the fence's middle line; 3.3 mm pilot holes in the fence.
# - A 3 mm wide, 5 mm deep V sighting notch on the centre line in the front edge of both
#   parts, to line up with a pencil mark.
# - A 6 mm hanging hole 12 mm in from the top-left corner.
# - Engraved: a centre line above the slot, "8 x 40 TENON", "17 mm BUSHING  8 mm BIT",
#   "19 mm STOCK".

import "std/fasteners.aidl"

thickness 6 mm

plate_w = 220 mm
plate_h = 140 mm
fence_h = 25 mm
bushing = 17 mm
play = 0.3 mm
bit = 8 mm
mortise_len = 40 mm
stock = 19 mm
slot_w = bushing + play
slot_len = mortise_len - bit + slot_w

fence_edge_y = -plate_h / 2 + fence_h     # the fence's inside edge, in the plate's frame
slot_y = fence_edge_y + stock / 2
screw_y = -plate_h / 2 + fence_h / 2
screw_xs = [-90 mm, -30 mm, 30 mm, 90 mm]

def sight_notch() -> hole {
    v = Polygon([(-1.5, 0.01), (1.5, 0.01), (0, -5)])
}

assembly mortise_template {
    solid plate {
        body = RoundedRectangle(center=(0, 0), width=plate_w, height=plate_h, corner_radius=6)
        hole guide {
            s = Slot(center=(0, slot_y), length=slot_len, width=slot_w)
        }
        hole hang {
            c = Circle(center=(-plate_w / 2 + 12, plate_h / 2 - 12), diameter=6)
        }
        hole notch {
            v = Polygon([(-1.5, -plate_h / 2 - 0.5), (1.5, -plate_h / 2 - 0.5), (0, -plate_h / 2 + 5)])
        }
        for i in range(4) {
            screw = clearance_hole(size=4, cx=screw_xs[i], cy=screw_y)
        }
        Countersink(screw, diameter=8)
        drawing marks {
            cl = Line((0, slot_y + slot_len / 2 + 3), (0, plate_h / 2 - 8))
            t1 = Text("8 x 40 TENON", position=(-45, 40), size=7, valign="middle")
            t2 = Text("17 mm BUSHING  8 mm BIT", position=(-45, 26), size=4, valign="middle")
            t3 = Text("19 mm STOCK", position=(55, 40), size=5, valign="middle")
        }
    }

    solid fence {
        body = Rectangle(center=(0, screw_y), width=plate_w, height=fence_h)
        hole notch {
            v = Polygon([(-1.5, -plate_h / 2 - 0.5), (1.5, -plate_h / 2 - 0.5), (0, -plate_h / 2 + 5)])
        }
        hole pilot {
            for i in range(4) {
                c = Circle(center=(screw_xs[i], screw_y), diameter=3.3)
            }
        }
    }

    # on the sheet: the fence below the plate
    Below(fence, plate, gap=6)
    AlignLeft(fence, plate)

    # 3D: the fence under the plate's front edge, the plate on top
    Place(fence, position=(0, 0, 0), face="up")
    Place(plate, position=(0, 0, 6 mm), face="up")

    assert plate.body.bb.width == 220 mm and plate.body.bb.height == 140 mm, "plate 220 x 140"
    assert fence.body.bb.width == 220 mm and fence.body.bb.height == 25 mm, "fence 220 x 25"
    assert plate.guide.s.width == 17.3 mm, "slot 17 mm bushing + 0.3 mm"
    assert plate.guide.s.length == 49.3 mm, "slot 40 - 8 + 17.3 long"
    assert plate.guide.s.center.y - (plate.body.bb.bottom + 25 mm) == 9.5 mm, "slot centre 9.5 mm from the fence edge"
    assert abs(plate.guide.s.center.x - plate.body.center.x) < 0.01 mm, "slot centred"
    assert len(plate.screw) == 4, "four screws"
    assert plate.screw[1].c.center.x - plate.body.center.x == -30 mm, "inner screw at 30 mm"
    assert plate.screw[3].c.center.x - plate.body.center.x == 90 mm, "outer screw at 90 mm"
    assert plate.screw[0].c.diameter > 4 mm, "M4 clearance"
}
