# Request: a wheel dishing gauge for 26" to 29" (700c) bike wheels, 9 mm birch ply. A bridge
# 664 mm long: two feet 50 mm wide reaching 90 mm below a 40 mm tall beam rest on the rim either
# side of the hub; R15 where the feet meet the beam, R10 on the beam's top corners. It is cut in
# two pieces (my bed is 600 x 400) joined 100 mm right of the centre by a 2-tail sliding
# dovetail 12 mm deep, glued. An M6 probe bolt comes down from the middle of the beam's bottom
# edge in a T-slot 28 mm long, its nut pocket 14 mm in; a 30 mm thumb-wheel with 12 scallops
# (6 mm) round its rim and an M6 nut pocket (+0.2 mm) jams the bolt. Engrave "DISHING GAUGE"
# (8 mm) on the left piece and "FLIP + COMPARE" (6 mm) on the right one.

import "std/joints.aidl"
import "std/fasteners.aidl"

thickness 9 mm

assembly gauge {
    solid left {
        beam = Rectangle(corner=(-332, 90), opposite=(112, 130))
        foot = Rectangle(corner=(-332, 0), opposite=(-282, 90))
        Fillet([foot.right, beam.bottom], 15)
        Fillet([beam.top, beam.left], 10)
        tails = dovetail(part="tail", length=40, depth=12, tails=2, angle=10, rotation=-90,
                         cx=100, cy=110)
        probe = t_slot(size=6, length=28, nut_depth=14, rotation=180, cx=0, cy=90)
        drawing word { t = Text("DISHING GAUGE", position=(-170, 110), size=8, valign="middle") }
    }
    solid right {
        beam = Rectangle(corner=(100, 90), opposite=(332, 130))
        foot = Rectangle(corner=(282, 0), opposite=(332, 90))
        Fillet([foot.left, beam.bottom], 15)
        Fillet([beam.top, beam.right], 10)
        socket = dovetail(part="socket", length=40, depth=12, tails=2, angle=10, rotation=-90,
                          cx=100, cy=110)
        drawing word { t = Text("FLIP + COMPARE", position=(216, 110), size=6, valign="middle") }
    }
    solid wheel {
        rim = Circle(center=(0, 0), diameter=30)
        hole scallop { c = Circle(center=(15, 0), diameter=6) }
        scallops = CircularPattern(scallop, 12, rim.center)
        nut = nut_trap(size=6, clearance=0.2)
    }

    # on the sheet: the right piece under the left, the wheel beside it
    Below(right, left, gap=5)
    AlignRight(right, left)
    Below(wheel, left, gap=5)
    AlignLeft(wheel, left)

    # in 3D: both pieces in their drawn frame (they meet at the dovetail), the wheel on the bolt
    Place(left, position=(0, 0, 0))
    Place(right, position=(0, 0, 0))
    Place(wheel, position=(0, 70, 4.5), face="back")

    assert right.beam.bb.right - left.beam.bb.left == 664 mm, "664 long"
    assert left.foot.width == 50 mm and right.foot.width == 50 mm, "feet 50 wide"
    assert left.beam.bb.bottom - left.foot.bb.bottom == 90 mm, "feet 90 below the beam"
    assert left.beam.height == 40 mm, "beam 40 tall"
    assert right.beam.bb.left - (left.beam.bb.left + right.beam.bb.right) / 2 == 100 mm,
        "joint 100 right of centre"
    assert left.beam.bb.right - right.beam.bb.left == 12 mm, "dovetail 12 deep"
    assert left.probe.slot.bb.height == 28 mm, "T-slot 28 long"
    assert abs(left.probe.slot.bb.center_x - (left.beam.bb.left + right.beam.bb.right) / 2) < 0.01 mm,
        "probe in the middle"
    assert wheel.rim.diameter == 30 mm, "thumb-wheel 30"
    assert len(wheel.scallops) == 12, "12 scallops"
    assert left.beam.bb.width <= 600 mm and right.beam.bb.width <= 600 mm, "fits the bed"
}
