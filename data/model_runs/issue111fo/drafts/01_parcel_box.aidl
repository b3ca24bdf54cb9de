# Request: a parcel drop box for the front step, in 6 mm exterior ply, with a hinged lid.
# Outside 400 mm long x 300 mm deep x 300 mm tall, finger joints 20 mm. The lid carries
# "PARCELS" engraved filled (bold sans, 40 mm capitals) with "thank you!" under it
# (serif, 16 mm), and two M5 clearance holes 96 mm apart, centred left-right and 30 mm
# in from the lid's front edge, for a 96 mm cabinet pull. The bottom has four 8 mm
# drainage holes, each 40 mm in from the outside corners of the box.

import "std/boxes.aidl"
import "std/fasteners.aidl"

thickness 6 mm

L = 400 mm
W = 300 mm
H = 300 mm

assembly parcel_box {
    box = hinged_box(length=L, width=W, height=H, thickness=6 mm, finger=20 mm)

    # the pull's two screws through the lid, near its front (-y) edge
    pull_a = clearance_hole(size=5)
    pull_b = clearance_hole(size=5)
    pull_a.c.center.x == box.lid.bb.center_x - 48 mm
    pull_b.c.center.x == box.lid.bb.center_x + 48 mm
    pull_a.c.center.y == box.lid.bb.bottom + 30 mm
    pull_b.c.center.y == box.lid.bb.bottom + 30 mm
    CutInto(pull_a, box.lid)
    CutInto(pull_b, box.lid)

    drawing label {
        word = Text("PARCELS", position=(0, 0), size=40, font="sans:Bold", valign="middle", fill=true)
        thanks = Text("thank you!", position=(0, -45), size=16, font="serif", valign="middle", fill=true)
    }
    AlignCenterX(label, box.lid)
    label.word.position.y == box.lid.bb.center_y + 30 mm
    CutInto(label, box.lid)

    # drainage: 40 mm in from the outside corners, i.e. +-160 and +-110 from the centre
    hole drains {
        for p in [(-1, -1), (1, -1), (1, 1), (-1, 1)] {
            d = Circle(center=(p[0] * (L / 2 - 40 mm), p[1] * (W / 2 - 40 mm)), diameter=8)
        }
    }
    CenterInside(drains, box.bottom)
    CutInto(drains, box.bottom)

    assert distance(pull_a.c.center, pull_b.c.center) == 96 mm, "a 96 mm pull"
    assert pull_a.c.center.y - box.lid.bb.bottom == 30 mm, "pull 30 mm from the front edge"
    assert len(drains.d) == 4, "four drainage holes"
    assert drains.d[0].diameter == 8 mm, "8 mm drainage holes"
    assert drains.d[1].center.x - drains.d[0].center.x == 400 mm - 2 * 40 mm, "40 mm in from the corners"
    assert drains.d[2].center.y - drains.d[1].center.y == 300 mm - 2 * 40 mm, "40 mm in from the corners"
    assert label.bb.width <= box.lid.bb.width - 40 mm, "the words fit on the lid"
}
