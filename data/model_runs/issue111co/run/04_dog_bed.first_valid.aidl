# Request: a raised-edge bed box for our terrier, Biscuit: outside 460 x 360 mm,
# walls 180 mm high, finger-jointed 6 mm ply, open top (a cushion goes in). The front
# dips in a smooth curve 240 mm wide down to 70 mm above the floor so she can step
# in; each side has a 90 x 25 mm hand slot 40 mm below its top edge to carry it; the
# back has BISCUIT engraved (filled bold letters, 40 mm tall); the bottom has 12
# air holes of 12 mm, 3 rows of 4, 90 mm apart. Laser bed 600 x 400 mm.

import "std/joints.aidl"

units mm
thickness 6 mm

param L = 460 mm, min = 360 mm, max = 580 mm
param Dp = 360 mm, min = 280 mm, max = 390 mm
param Hw = 180 mm, min = 120 mm, max = 250 mm
param step_h = 70 mm, min = 40 mm, max = 120 mm   # the dip's lowest point above the floor
param dip_w = 240 mm, min = 160 mm, max = 320 mm

def vent() -> hole {
    c = Circle(center=(0, 0), diameter=12)
}

def hand_slot() -> hole {
    s = Slot(center=(0, 0), length=90, width=25, rotation=90 deg)
}

assembly dog_bed {
    box = finger_box(length=L, depth=Dp, height=Hw, thickness=6 mm, finger=25 mm,
                     closed=false, gap=6 mm)

    # the entry: a half-ellipse dip in the front's top edge
    hole entry {
        e = Ellipse(center=(0, 0), rx=dip_w / 2, ry=Hw - step_h)
    }
    AlignCenterX(entry, box.front)
    entry.e.center.y == box.front.bb.top
    CutInto(entry, box.front)

    # hand slots, 40 mm below each side's top edge (the left's top edge is at -x,
    # the right's at +x, as finger_box lays them)
    lh = hand_slot()
    rh = hand_slot()
    AlignCenterY(lh, box.left)
    lh.s.center.x == box.left.bb.left + 40 mm
    AlignCenterY(rh, box.right)
    rh.s.center.x == box.right.bb.right - 40 mm
    CutInto(lh, box.left)
    CutInto(rh, box.right)

    # the name on the back
    drawing name {
        n = Text("BISCUIT", position=(0, 0), size=40, font="sans:Bold", valign="middle",
                 fill=true)
    }
    AlignCenterX(name, box.back)
    name.n.position.y == box.back.bb.top - 70 mm
    CutInto(name, box.back)

    # air holes in the bottom
    v = vent()
    vents = GridPattern(v, 3, 4, (90 mm, 90 mm))
    At(v.c.center, box.bottom.bb.center, dx=-135, dy=-90)
    CutInto(v, box.bottom)

    # the request's numbers
    assert box.bottom.bb.width == 460 mm and box.left.bb.height == 360 mm, "460 x 360 outside"
    assert box.front.bb.height == 180 mm, "walls 180 mm high"
    assert entry.e.rx * 2 == 240 mm, "dip 240 mm wide"
    assert box.front.bb.top - entry.bb.bottom == 180 mm - 70 mm, "dip down to 70 mm above the floor"
    assert lh.s.length == 90 mm and lh.s.width == 25 mm, "90 x 25 hand slots"
    assert lh.s.center.x - box.left.bb.left == 40 mm, "40 mm below the top edge"
    assert name.n.size == 40 mm, "40 mm letters"
    assert len(vents) == 12 and v.c.diameter == 12 mm, "12 air holes of 12 mm"
    assert box.bottom.bb.width <= 600 mm and box.bottom.bb.height <= 400 mm, "fits the bed"
}
