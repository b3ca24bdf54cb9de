# Request (electronics): an enclosure for an attic temperature/humidity node, 3 mm ply.
# - The board: a 70 x 30 mm perfboard with an ESP32 and a BME280, M2.5 holes (2.7 mm)
#   3.5 mm in from each corner, on 5 mm standoffs; 2 mm clearance to every wall,
#   30 mm inside from floor to lid, 10 mm fingers.
# - A 12 x 7 mm opening for the USB-C plug in the left end, centred on the board's
#   width (y = 15 on the board).
# - A hex vent in the lid; on the right end a 4 x 4 grid of 4 mm air holes on a 7 mm
#   pitch, centred, for the humidity sensor.
# - On the front wall: a 5 mm light-pipe hole 20 mm from the right end and 12 mm up
#   from the outside bottom, and "ATTIC 3" engraved 7 mm high, its right end 10 mm left
#   of the light pipe, centred on the wall's height.
# - Two keyholes (8 mm head, 4 mm slot, 10 mm long) in the floor, 40 mm apart on its
#   centre line along the length, slots toward the right end: it hangs with the USB
#   end down.

import "std/enclosures.aidl"
import "std/plates.aidl"

thickness 3 mm

board_w = 70 mm
board_h = 30 mm

assembly sensor_node_box {
    box = board_enclosure(width=board_w, height=board_h, depth=30 mm, thickness=3 mm,
                          clearance=2 mm,
                          holes=[[3.5, 3.5], [board_w - 3.5, 3.5], [3.5, board_h - 3.5],
                                 [board_w - 3.5, board_h - 3.5]],
                          hole_d=2.7 mm, standoff=5 mm,
                          ports=[["left", board_h / 2, 12, 7]], vent="hex", finger=10 mm)

    # air holes in the right end
    hole air {
        a = Circle(center=(0, 0), diameter=4)
    }
    air_grid = GridPattern(air, 4, 4, 7 mm)
    CutInto(air, box.right)
    (air.a.center.x + 10.5 mm == box.right.bb.center_x and
     air.a.center.y + 10.5 mm == box.right.bb.center_y)

    # light pipe and label on the front wall
    hole light {
        c = Circle(center=(0, 0), diameter=5)
    }
    CutInto(light, box.front)
    light.c.center.x == box.front.bb.right - 20 mm
    light.c.center.y == box.front.bb.bottom + 12 mm

    drawing label {
        t = Text("ATTIC 3", position=(0, 0), size=7, anchor="end", valign="middle")
    }
    CutInto(label, box.front)
    label.t.position.x == light.c.center.x - 10 mm
    label.t.position.y == box.front.bb.center_y

    # keyholes in the floor, slots toward the right end
    lower = keyhole(head=8 mm, slot_width=4 mm, length=10 mm, direction=0 deg)
    upper = keyhole(head=8 mm, slot_width=4 mm, length=10 mm, direction=0 deg)
    CutInto(lower, box.bottom)
    CutInto(upper, box.bottom)
    AlignCenterY(lower.head_hole, box.bottom)
    AlignCenterY(upper.head_hole, box.bottom)
    lower.head_hole.center.x == box.bottom.bb.center_x - 25 mm
    upper.head_hole.center.x == lower.head_hole.center.x + 40 mm

    # the request's numbers
    assert box.tall == 30 mm + 2 * 3 mm, "30 mm inside, floor to lid"
    assert box.length == 70 mm + 2 * 2 mm + 2 * 3 mm, "2 mm clearance each end"
    assert len(air_grid) == 16, "4 x 4 air holes"
    assert air_grid[1].a.center.x - air_grid[0].a.center.x == 7 mm, "7 mm pitch"
    assert box.front.bb.right - light.c.center.x == 20 mm, "light pipe 20 from the right end"
    assert light.c.center.y - box.front.bb.bottom == 12 mm, "light pipe 12 up"
    assert upper.head_hole.center.x - lower.head_hole.center.x == 40 mm, "keyholes 40 apart"
}
