# Request: a three-board burr puzzle for my nephew. 6 mm birch ply, three boards 90 x 30 mm with
# R3 corners that lock together at right angles through each other's middles. Boards A and B
# each have a central window 30 x 6 mm along their length (plus 0.4 mm clearance in length and
# 0.2 mm in width: 30.4 x 6.2); C is the key: a 6.2 mm slot centred across it, 60 mm deep from
# one end. A goes through B's window, then C slides along its slot over B and through A's
# window. Each board has its letter engraved 10 mm tall near its left end; A also says "BURR"
# (6 mm) near its right end. Show it assembled in 3D.

import "std/joints.aidl"

thickness 6 mm

def board(name="A", window=true) -> solid {
    body = RoundedRectangle(center=(0, 0), width=90, height=30, corner_radius=3)
    if window {
        hole win { w = Rectangle(center=(0, 0), width=30.4, height=6.2) }
    } else {
        key = cross_halving(depth=60, thickness=6, clearance=0.2, rotation=-90, cx=45, cy=0)
    }
    drawing letter { t = Text(name, position=(-32, 0), size=10, valign="middle", font="sans:Bold") }
}

assembly burr {
    a = board(name="A", window=true)
    b = board(name="B", window=true)
    c = board(name="C", window=false)
    drawing a_word { t = Text("BURR", position=(30, 0), size=6, valign="middle") }
    CutInto(a_word, a)

    # flat on the sheet: one under the other
    Below(b, a, gap=5)
    AlignLeft(b, a)
    Below(c, b, gap=5)
    AlignLeft(c, b)

    # in 3D: A along x (flat), B along y (on edge, facing +x), C along z (upright, facing +y)
    Place(a, position=(0, 0, -3))
    Place(b, position=(-3, 0, 0), face="right", up="up")
    Place(c, position=(0, -3, 0), face="back", up="right")

    assert a.body.bb.width == 90 mm and a.body.bb.height == 30 mm, "boards 90 x 30"
    assert a.win.w.width == 30.4 mm and a.win.w.height == 6.2 mm, "window 30.4 x 6.2"
    assert abs(a.win.w.center.x - a.body.center.x) < 0.01 mm, "window central"
    assert c.key.cut.bb.width == 60 mm, "key slot 60 deep"
    assert c.key.cut.bb.height == 6.2 mm, "key slot 6.2 wide"
    assert abs(c.key.cut.bb.center_y - c.body.center.y) < 0.01 mm, "key slot centred across"
    assert a.win.w.width >= c.body.bb.height, "C passes through A's window"
    assert b.win.w.width >= a.body.bb.height, "A passes through B's window"
    assert c.key.cut.bb.width - 45 mm >= b.body.bb.height / 2, "C's slot reaches past B"
}
