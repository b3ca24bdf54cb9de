# Holidays (Hanukkah): a 3D dreidel decoration from two cross-halved 3 mm plywood
# panels. Each panel: a square body 60 x 60 mm, a point below it (triangle 60 wide at
# its base, 30 mm tall) and a handle above it (10 wide, 30 tall), 120 mm tall in all,
# centred on one vertical axis. Panel A has a cross-halving slot 60 mm deep down from
# the top of the handle; panel B has one 60 mm deep up from the tip of the point;
# slots 3 mm wide plus 0.1 mm clearance. The four letters N, G, H, S (nun, gimel, hei,
# shin) engraved, stroke text 16 mm high, centred on the body's left and right halves
# (A: N and G, B: H and S). The panels lie side by side 10 mm apart for cutting.

import "std/joints.aidl"

units mm
thickness 3 mm

assembly dreidel {
    solid a {
        body = Rectangle(center=(0, 0), width=60, height=60)
        point = Triangle(center=(0, -45), base=60, height=30, rotation=180 deg)
        handle = Rectangle(center=(0, 45), width=10, height=30)
        slot = cross_halving(depth=60 mm, thickness=3 mm, clearance=0.1 mm, cx=0 mm, cy=60 mm)
        drawing letters {
            l1 = Text("N", (-16, 0), size=16, valign="middle")
            l2 = Text("G", (16, 0), size=16, valign="middle")
        }
    }

    solid b {
        body = Rectangle(center=(0, 0), width=60, height=60)
        point = Triangle(center=(0, -45), base=60, height=30, rotation=180 deg)
        handle = Rectangle(center=(0, 45), width=10, height=30)
        slot = cross_halving(depth=60 mm, thickness=3 mm, clearance=0.1 mm, rotation=180 deg,
                             cx=0 mm, cy=-60 mm)
        drawing letters {
            l1 = Text("H", (-16, 0), size=16, valign="middle")
            l2 = Text("S", (16, 0), size=16, valign="middle")
        }
    }
    Rigid(b)
    RightOf(b, a, gap=10)
    AlignBottom(b, a)

    # the request's numbers
    assert a.body.width == 60 mm and a.body.height == 60 mm, "body 60 x 60"
    assert a.point.bb.width == 60 mm and a.point.bb.height == 30 mm, "point 60 x 30"
    assert a.point.bb.top == a.body.bb.bottom, "point under the body"
    assert a.handle.width == 10 mm and a.handle.height == 30 mm, "handle 10 x 30"
    assert a.handle.bb.bottom == a.body.bb.top, "handle on the body"
    assert a.bb.height == 120 mm and b.bb.height == 120 mm, "120 tall in all"
    assert a.slot.cut.bb.height == 60 mm and b.slot.cut.bb.height == 60 mm, "slots 60 deep"
    assert a.slot.cut.bb.width == 3.1 mm, "slot 3 + 0.1 wide"
    assert a.slot.cut.bb.top == a.handle.bb.top, "A's slot from the top of the handle"
    assert b.slot.cut.bb.bottom == b.point.bb.bottom, "B's slot from the tip"
    assert a.slot.cut.bb.height + b.slot.cut.bb.height == a.bb.height, "the slots add up to the height"
    assert a.letters.l1.size == 16 mm, "16 mm letters"
    assert a.letters.l1.position.x - a.body.center.x == -16 mm, "left letter on the left half"
    assert a.letters.bb.bottom > a.body.bb.bottom and a.letters.bb.top < a.body.bb.top, "letters on the body"
    assert b.bb.left - a.bb.right == 10 mm, "10 mm apart"
}
