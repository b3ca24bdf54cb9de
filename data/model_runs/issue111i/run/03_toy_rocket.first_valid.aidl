# Stand-up toy rocket: two identical 3 mm plywood profiles slotted into each other
# crosswise (cross halving). Each profile is 180 mm tall and 60 mm wide across the
# fins: a 30 mm wide body from 8 mm to 130 mm up, a pointed nose cone on top (50 mm
# tall, apex at 180 mm), and two fins that reach the ground 30 mm out from the middle
# (fin tip edge vertical, 22 mm tall, sloping back into the body 60 mm up).
# Piece A is slotted from the nose down 90 mm; piece B from the bottom up 90 mm
# (the body's bottom edge, 8 mm up); slots 3.1 mm wide (3 mm ply + 0.1 mm clearance).
# Piece B has a 12 mm porthole on its centre line, 20 mm below the nose's base.
# On the sheet: A left, B right, 10 mm apart, bottoms aligned.

units mm
thickness 3 mm

import "std/joints.aidl"

param ply = 3 mm, min = 2.5 mm, max = 4 mm

def rocket(top_slot=true) -> solid {
    outline = Polygon([(0, 8), (15, 8), (30, 0), (30, 22), (15, 60), (15, 130), (0, 180)], mirror="y")
    if top_slot {
        slot = cross_halving(depth=90 mm, thickness=ply, clearance=0.1 mm, cx=0 mm, cy=180 mm)
    } else {
        slot = cross_halving(depth=90 mm, thickness=ply, clearance=0.1 mm, rotation=180 deg, cx=0 mm, cy=8 mm)
        hole porthole {
            c = Circle(center=(0, 110), diameter=12)
        }
    }
}

assembly toy {
    a = rocket(top_slot=true)
    b = rocket(top_slot=false)
    RightOf(b, a, gap=10)
    AlignBottom(b, a)

    assert a.outline.bb.height == 180 mm and a.outline.bb.width == 60 mm, "180 tall, 60 across the fins"
    assert b.outline.bb.height == 180 mm and b.outline.bb.width == 60 mm, "B the same"
    assert a.slot.cut.bb.width == 3.1 mm, "slot 3.1 wide"
    assert a.outline.bb.top - a.slot.cut.bb.bottom == 90 mm, "A slotted 90 mm from the nose"
    assert b.slot.cut.bb.top - (b.outline.bb.bottom + 8 mm) == 90 mm, "B slotted 90 mm up from the body's bottom"
    assert b.porthole.c.diameter == 12 mm, "12 mm porthole"
    assert (b.outline.bb.bottom + 130 mm) - b.porthole.c.center.y == 20 mm, "porthole 20 mm below the nose base"
    assert abs(b.porthole.c.center.x - b.outline.bb.center_x) < 0.01 mm, "porthole on the centre line"
    assert b.outline.bb.left - a.outline.bb.right == 10 mm, "10 mm apart"
}
