# Gifts: two-piece puzzle gift card, 3 mm birch. Assembled 86 x 54 mm (a credit card's size),
# outer corners R4, split down the middle into two 43 mm halves locked by a flat sliding
# dovetail along the 54 mm split: two tails 8 mm deep, 10 deg, on the left half, 0.1 mm
# clearance in the right half's sockets. "HAPPY" engraved 6 mm on the left half, "BIRTHDAY"
# 5 mm on the right half, each centred in its half's plain area.
import "std/joints.aidl"

thickness 3 mm

assembly card {
    solid left {
        body = RoundedRectangle(center=(-17.5, 0), width=51, height=54, corner_radii=[4, 0, 0, 4])
        tails = dovetail(part="tail", length=54 mm, depth=8 mm, tails=2, angle=10 deg, rotation=-90 deg, cx=0 mm, cy=0 mm)
        drawing word {
            w = Text("HAPPY", (-21.5, 0), size=6, valign="middle")
        }
    }
    solid right {
        body = RoundedRectangle(center=(21.5, 0), width=43, height=54, corner_radii=[0, 4, 4, 0])
        sockets = dovetail(part="socket", length=54 mm, depth=8 mm, tails=2, angle=10 deg, clearance=0.1 mm, rotation=-90 deg, cx=0 mm, cy=0 mm)
        drawing word {
            w = Text("BIRTHDAY", (25.5, 0), size=5, valign="middle")  # (fix: max_width shrank it to 4.5 mm; 5 mm was asked)
        }
    }
    RightOf(right, left, gap=6)
    AlignCenterY(right, left)

    assert left.body.bb.width - 8 mm + right.body.bb.width == 86 mm, "86 long assembled"
    assert left.body.bb.height == 54 mm and right.body.bb.height == 54 mm, "54 tall"
    assert right.body.bb.width == 43 mm, "43 mm halves"
    assert left.tails.bb.width == 8 mm, "tails 8 deep"
}
