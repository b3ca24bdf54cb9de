# Request: a garden soil sieve (a riddle) that sits over a wheelbarrow, 6 mm exterior ply,
# finger-jointed with 30 mm fingers: 350 x 350 mm outside, 100 mm deep, open at the top.
# The bottom is the mesh: 18 x 18 square holes 12 mm across on a 16 mm pitch (4 mm webs),
# centred. A 100 x 30 mm hand hole along each side panel (left and right), its centre 35 mm
# below the top edge, centred along the side. The mesh size "12 mm" engraved filled on the
# front, 20 mm bold, centred, its middle 40 mm below the top edge.

import "std/joints.aidl"

thickness 6 mm

HOLE = 12 mm
PITCH = 16 mm
N = 18

assembly sieve {
    box = finger_box(length=350 mm, depth=350 mm, height=100 mm, thickness=6 mm, finger=30 mm,
                     closed=false)

    hole mesh {
        sq = Rectangle(center=(0, 0), width=HOLE, height=HOLE)
        grid = GridPattern(sq, N, N, (PITCH, PITCH))
    }
    CenterInside(mesh, box.bottom)
    CutInto(mesh, box.bottom)

    # the sides lie on their side in the net: the left's top edge at -x, the right's at +x
    hole hand_left { s = Slot(center=(0, 0), length=100, width=30) }
    hole hand_right { s = Slot(center=(0, 0), length=100, width=30) }
    AlignCenterY(hand_left, box.left)
    AlignCenterY(hand_right, box.right)
    hand_left.s.center.x == box.left.bb.left + 35 mm
    hand_right.s.center.x == box.right.bb.right - 35 mm
    CutInto(hand_left, box.left)
    CutInto(hand_right, box.right)

    drawing size_mark {
        t = Text("12 mm", position=(0, 0), size=20, font="sans:Bold", valign="middle", fill=true)
    }
    AlignCenterX(size_mark, box.front)
    size_mark.t.position.y == box.front.bb.top - 40 mm
    CutInto(size_mark, box.front)

    # the request's numbers
    assert box.front.bb.width == 350 mm and box.left.bb.height == 350 mm, "350 x 350 outside"
    assert box.front.bb.height == 100 mm, "100 mm deep"
    assert len(mesh.grid) == 18 * 18, "18 x 18 holes"
    assert mesh.grid[1].center.x - mesh.grid[0].center.x == 16 mm, "16 mm pitch"
    assert mesh.sq.width == 12 mm, "12 mm holes"
    assert box.left.bb.left + 35 mm == hand_left.s.center.x, "hand hole 35 mm below the top"
    assert mesh.bb.left - box.bottom.bb.left == box.bottom.bb.right - mesh.bb.right, "mesh centred"
}
