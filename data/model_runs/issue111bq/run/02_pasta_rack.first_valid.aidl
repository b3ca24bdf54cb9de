# Request: a fresh-pasta drying rack, 6 mm birch ply. Two uprights cross-halved at their middle
# stand as an X on the worktop. Each upright: a 40 mm wide mast, a 240 x 25 mm foot at the
# bottom (with a 160 mm wide, 4 mm high relief under it so it stands on its ends), and two
# 22 mm tall arms with round ends that the tagliatelle hang over. Upright A: 360 mm tall, a
# 320 mm arm at the top and a 240 mm arm whose top is at 250 mm. Upright B: 310 mm tall, a
# 280 mm arm at the top and a 200 mm arm whose top is at 200 mm (so the four arms are at four
# heights). A is slotted up from the bottom, B down from the top, each halfway up B's height,
# 0.2 mm clearance. Inside corners where the arms and foot meet the mast: r6. "PASTA" engraved
# on A's top arm.
units mm
thickness 6 mm
import "std/joints.aidl"

T = 6 mm
MAST = 40 mm
ARM_H = 22 mm
FOOT_W = 240 mm
FOOT_H = 25 mm
A_H = 360 mm
B_H = 310 mm
HALF = B_H / 2

def upright(height, top_len, mid_top, mid_len, slot_from_top) -> solid {
    mast = Rectangle(bottom_left=(-MAST / 2, 0), width=MAST, height=height)
    foot = Rectangle(bottom_left=(-FOOT_W / 2, 0), width=FOOT_W, height=FOOT_H)
    top_arm = RoundedRectangle(center=(0, height - ARM_H / 2), width=top_len, height=ARM_H,
                               corner_radius=ARM_H / 2)
    mid_arm = RoundedRectangle(center=(0, mid_top - ARM_H / 2), width=mid_len, height=ARM_H,
                               corner_radius=ARM_H / 2)
    hole relief { r = Rectangle(center=(0, 1), width=160, height=6) }
    Fillet([[mast.left, foot.top], [mast.right, foot.top],
            [mast.left, top_arm.bottom], [mast.right, top_arm.bottom],
            [mast.left, mid_arm.bottom], [mast.right, mid_arm.bottom],
            [mast.left, mid_arm.top], [mast.right, mid_arm.top]], 6)
    if slot_from_top {
        halving = cross_halving(depth=HALF, thickness=T, clearance=0.2 mm, cx=0, cy=height)
    } else {
        halving = cross_halving(depth=HALF, thickness=T, clearance=0.2 mm, rotation=180 deg,
                                cx=0, cy=0)
    }
}

assembly pasta_rack {
    a = upright(height=A_H, top_len=320 mm, mid_top=250 mm, mid_len=240 mm, slot_from_top=false)
    b = upright(height=B_H, top_len=280 mm, mid_top=200 mm, mid_len=200 mm, slot_from_top=true)
    drawing label {
        word = Text("PASTA", position=(0, A_H - ARM_H / 2), size=12, valign="middle")
    }
    CutInto(label, a)
    AlignCenterX(label, a.top_arm)
    AlignCenterY(label, a.top_arm)

    # on the sheet
    RightOf(b, a, gap=8)
    AlignBottom(b, a)

    # in 3D: A in the x-z plane, B in the y-z plane, crossing at the z axis
    Place(a, rotation=(90 deg, 0, 0), position=(0, T / 2, 0))
    Place(b, rotation=(90 deg, 0, 90 deg), position=(-T / 2, 0, 0))

    assert a.mast.bb.height == 360 mm and b.mast.bb.height == 310 mm, "heights 360 and 310"
    assert a.top_arm.bb.width == 320 mm and a.mid_arm.bb.width == 240 mm, "A's arms"
    assert b.top_arm.bb.width == 280 mm and b.mid_arm.bb.width == 200 mm, "B's arms"
    assert a.mid_arm.bb.top - a.foot.bb.bottom == 250 mm, "A's middle arm top at 250"
    assert b.mid_arm.bb.top - b.foot.bb.bottom == 200 mm, "B's middle arm top at 200"
    assert a.halving.cut.bb.height + b.halving.cut.bb.height == 310 mm, "halvings meet"
}
