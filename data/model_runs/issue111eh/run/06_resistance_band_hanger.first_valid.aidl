# Request (sport): a wall rack for five resistance bands (loops), 6 mm birch plywood.
# Back plate 420 x 110 mm, R8 corners, on four M5 countersunk screws (5.5 mm holes, 10.5 mm
# heads) 15 mm in from each corner. Five pegs 80 mm apart, centred, at mid-height. Each
# peg is a side-profile piece standing out 100 mm from the plate's face: 25 mm tall at the
# plate, its underside rising to 3.5 mm higher at the tip, its top falling to 9 mm above
# the axis, and a lip at the tip 10 mm long rising 12 mm above the arm's top so the band
# can't slide off (lip corners R3). The peg passes through the plate on two 8 mm tenons into
# mortises with 0.2 mm clearance, flush at the back. Labels engraved filled under each peg,
# 7 mm sans bold, centred 32 mm below the axis: X-LIGHT, LIGHT, MEDIUM, HEAVY, X-HEAVY.

import "std/joints.aidl"

thickness 6 mm

t = 6 mm
names = ["X-LIGHT", "LIGHT", "MEDIUM", "HEAVY", "X-HEAVY"]

# a peg in side view: x out from the plate's face (tenon tips at x = -t, flush with the
# plate's back), y up from the peg's axis
def peg() -> solid {
    arm = Polygon([(-t, -12.5), (100, -9), (100, 21), (90, 21), (90, 9), (-t, 12.5)])
    Fillet([arm.points[2], arm.points[3]], 3 mm)
    root = tab_and_slot(part="tab", length=25 mm, thickness=t, tabs=2, tab=8 mm, screw=0,
                        rotation=90 deg, cx=-t, cy=0)
}

assembly band_rack {
    solid back {
        plate = RoundedRectangle(center=(0, 0), width=420, height=110, corner_radius=8)
        hole screw {
            c = Circle(center=(0, 0), diameter=5.5)
        }
        corners = CornerPattern(screw, plate, inset=15 mm)
        Countersink(corners, diameter=10.5 mm)
        for i in range(5) {
            m = tab_and_slot(part="slot", length=25 mm, thickness=t, tabs=2, tab=8 mm,
                             screw=0, clearance=0.2 mm, rotation=90 deg,
                             cx=(i - 2) * 80 mm, cy=0)
            drawing label {
                n = Text(names[i], position=((i - 2) * 80 mm, -32), size=7, font="sans:Bold",
                         valign="middle", fill=true)
            }
        }
    }
    for i in range(5) {
        p = peg()
        Place(p, position=((i - 2) * 80 mm + t / 2, -t, 0), face="left", up="up")
    }

    # laid out flat: the pegs in a row under the plate
    Below(p[0], back, gap=5)
    AlignLeft(p[0], back)
    for i in range(1, 5) {
        RightOf(p[i], p[i - 1], gap=5)
        AlignBottom(p[i], p[0])
    }
    Place(back, position=(0, 0, 0), face="front", up="up")

    # the request's numbers
    assert back.plate.bb.width == 420 mm and back.plate.bb.height == 110 mm, "plate 420 x 110"
    assert len(p) == 5 and len(back.m) == 5, "five pegs, five mortise pairs"
    assert back.m[1].slot[0].bb.center_x - back.m[0].slot[0].bb.center_x == 80 mm, "80 apart"
    assert p[0].arm.bb.right - (p[0].arm.bb.left + 6 mm) == 100 mm, "pegs stand out 100"
    assert p[0].arm.bb.top - (p[0].arm.bb.bottom + 12.5 mm) == 21 mm, "lip 12 above a 9 top"
    assert back.corners[0].c.center.x - back.plate.bb.left == 15 mm, "screws 15 in"
    assert back.corners[0].c.center.y - back.plate.bb.bottom == 15 mm, "screws 15 in"
    assert distance(back.label, back.m) >= 5 mm, "labels clear of the mortises"
    assert distance(back.label, back.corners) >= 5 mm, "labels clear of the screws"
    assert back.label[0].bb.width <= 80 mm - 10 mm, "labels fit the pitch"
}
