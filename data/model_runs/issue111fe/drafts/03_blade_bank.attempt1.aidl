# Request (bathroom): a blade bank for used double-edge razor blades (43 x 22 mm), to hang
# inside the bathroom cabinet and go to the metal recycling when full.
# 3 mm birch ply, a closed finger-jointed box 70 wide x 30 deep x 110 tall outside, 10 mm
# fingers, glued shut for good.
# - lid (top): a 48 x 2 mm slot in the middle for posting a blade (a blade is 43 long).
# - front: a warning triangle (36 base, 31 high, 2.5 mm filled border, "!" inside) 12 mm
#   below the top, then "USED" and "BLADES" filled, 10 mm letters, and "RECYCLE WHEN FULL"
#   in 3.5 mm single-stroke letters near the bottom.
# - back: a keyhole (8 mm head, 4 mm slot 10 long, upward) centred 30 mm below the top, to
#   hang it on a screw.

units mm
thickness 3 mm

import "std/joints.aidl"
import "std/plates.aidl"

assembly blade_bank {
    box = finger_box(length=70 mm, depth=30 mm, height=110 mm, thickness=3 mm, finger=10 mm)

    hole post {
        s = Slot(center=(0, 0), length=48, width=2)
    }
    CenterInside(post, box.lid)
    CutInto(post, box.lid)

    drawing warning {
        tri = Triangle(center=(0, 0), base=36, height=31, construction=true)
        border = Shell(tri, thickness=-2.5, fill=true)
        bang = Text("!", position=(0, -4), size=14, font="sans:Bold", valign="middle",
                    fill=true)
        used = Text("USED", position=(0, -32), size=10, font="sans:Bold", valign="middle",
                    fill=true)
        blades = Text("BLADES", position=(0, -48), size=10, font="sans:Bold",
                      valign="middle", fill=true)
        note = Text("RECYCLE WHEN FULL", position=(0, -80), size=3.5, valign="middle")
    }
    AlignCenterX(warning, box.front)
    warning.bb.top == box.front.bb.top - 12 mm
    CutInto(warning, box.front)

    hang = keyhole(head=8 mm, slot_width=4 mm, length=10 mm, direction=90 deg)
    AlignCenterX(hang, box.back)
    hang.head_hole.center.y == box.back.bb.top - 30 mm
    CutInto(hang, box.back)

    # the request's numbers
    assert box.front.bb.width == 70 mm and box.front.bb.height == 110 mm, "70 x 110 front"
    assert box.left.bb.width == 110 mm and box.left.bb.height == 30 mm, "30 deep"
    assert post.s.length == 48 mm and post.s.width == 2 mm, "48 x 2 slot"
    assert post.s.length - 43 mm >= 4 mm, "a blade goes in with room"
    assert abs(post.bb.center_x - box.lid.bb.center_x) < 0.01 mm and
        abs(post.bb.center_y - box.lid.bb.center_y) < 0.01 mm, "slot in the lid's middle"
    assert box.front.bb.top - warning.bb.top == 12 mm, "triangle 12 below the top"
    assert warning.tri.base == 36 mm and warning.tri.height == 31 mm, "triangle 36 x 31"
    assert warning.bb.bottom > box.front.bb.bottom + 6 mm, "engraving clear of the fingers"
    assert warning.bb.width < box.front.bb.width - 12 mm, "engraving clear of the sides"
    assert box.back.bb.top - hang.head_hole.center.y == 30 mm, "keyhole 30 below the top"
    assert hang.head_hole.diameter == 8 mm, "8 mm head"
}
