# Request (workshop): a small mitre box for cutting picture-frame moulding and
# strip wood up to 30 mm wide with a Japanese pull saw (blade kerf ~0.9 mm),
# from 6 mm birch ply. A base 220 x 80 mm (R4 corners) with two fences glued in
# standing on it, 220 long and 45 mm tall above the base, leaving a 30 mm wide
# channel between them. Each fence has three 30 mm tenons through mortises in the
# base (0.1 mm clearance). Saw notches run from the fences' top edges down to
# 3 mm above the base: a 1.0 mm notch for 90 deg cuts 60 mm left of centre, and
# two 45 deg notches (crossing at 40 mm right of centre) each 6 mm + 1.0 x sqrt(2)
# wide so the blade passes the 6 mm fence at 45 deg. "90°" and "45°" engraved
# (filled, 7 mm) on the outside of both fences. Four M4 countersunk holes in the
# base's ledges to screw it to a bench hook.

import "std/joints.aidl"
import "std/fasteners.aidl"

units mm
thickness 6 mm

T = 6 mm              # ply thickness
L = 220 mm            # box length
BASE_W = 80 mm
FENCE_UP = 45 mm      # fence height above the base
CHANNEL = 30 mm
KERF_NOTCH = 1.0 mm
NOTCH_45 = T + KERF_NOTCH * sqrt(2)
H = FENCE_UP + T      # fence height including the tenon row
MID = CHANNEL / 2 + T / 2   # fence mid-plane from the box's centre line
X90 = -60 mm
X45 = 40 mm           # where the two 45 deg lines cross (on the centre line)

# One fence. s = 1: the front fence, drawn as seen from the front;
# s = -1: the back fence, drawn as seen from behind (world x = -local x).
def fence(s=1) -> solid {
    body = Rectangle(bottom_left=(-L / 2, 0), width=L, height=H)
    Fixed(body)
    tenons = tab_and_slot(part="tab", length=L, thickness=T, tabs=3, tab=30 mm,
                          screw=0, rotation=180 deg, cx=0 mm, cy=0 mm)
    hole notches {
        n90 = Rectangle(center=(s * X90, H - (H - T - 3 mm) / 2 + 0.5 mm),
                        width=KERF_NOTCH, height=H - T - 3 mm + 1 mm)
        # the 45 deg lines cross the fence mid-plane MID either side of X45
        na = Rectangle(center=(s * (X45 - MID), H - (H - T - 3 mm) / 2 + 0.5 mm),
                       width=NOTCH_45, height=H - T - 3 mm + 1 mm)
        nb = Rectangle(center=(s * (X45 + MID), H - (H - T - 3 mm) / 2 + 0.5 mm),
                       width=NOTCH_45, height=H - T - 3 mm + 1 mm)
    }
    drawing labels {
        l90 = Text("90°", position=(s * (X90 + 16 mm), T + 22 mm), size=7,
                   valign="middle", font="sans:Bold", fill=true)
        l45 = Text("45°", position=(s * X45, T + 22 mm), size=7,
                   valign="middle", font="sans:Bold", fill=true)
    }
}

assembly mitre_box {
    solid base {
        body = RoundedRectangle(center=(0, 0), width=L, height=BASE_W, corner_radius=4)
        Fixed(body)
        front_mortise = tab_and_slot(part="slot", length=L, thickness=T, tabs=3, tab=30 mm,
                                     screw=0, clearance=0.1 mm, cx=0 mm, cy=-MID)
        back_mortise = tab_and_slot(part="slot", length=L, thickness=T, tabs=3, tab=30 mm,
                                    screw=0, clearance=0.1 mm, cx=0 mm, cy=MID)
        h1 = clearance_hole(size=4, cx=-95 mm, cy=-30 mm)
        h2 = clearance_hole(size=4, cx=95 mm, cy=-30 mm)
        h3 = clearance_hole(size=4, cx=-95 mm, cy=30 mm)
        h4 = clearance_hole(size=4, cx=95 mm, cy=30 mm)
        Countersink([h1, h2, h3, h4], diameter=8.5 mm)
    }
    front = fence(s=1)
    back = fence(s=-1)

    # flat on the sheet: fences above the base
    Above(front, base, gap=5)
    AlignCenterX(front, base)
    Above(back, front, gap=5)
    AlignCenterX(back, base)

    # in 3D: base flat, fences standing on it, engraving outward
    Place(base, position=(0, 0, 0), face="up")
    Place(front, position=(0, -CHANNEL / 2, 0), face="front", up="up")
    Place(back, position=(0, CHANNEL / 2, 0), face="back", up="up")

    # the request's numbers
    assert base.body.bb.width == 220 mm, "base 220 long"
    assert base.body.bb.height == 80 mm, "base 80 deep"
    assert front.body.bb.height - 6 mm == 45 mm, "fence 45 above the base"
    assert 2 * MID - T == 30 mm, "30 mm channel"
    assert abs(front.notches.na.bb.width - (6 mm + 1.0 mm * sqrt(2))) < 0.001 mm, "45 deg notch width"
    assert front.notches.n90.bb.width == 1.0 mm, "90 deg notch 1.0 wide"
    assert front.notches.n90.bb.bottom - front.body.bb.bottom == 6 mm + 3 mm, "notches stop 3 above the base"
    assert (front.notches.na.bb.center_x + front.notches.nb.bb.center_x) / 2 - front.body.bb.center_x == 40 mm,
        "45 deg lines cross 40 right of centre"
    assert front.notches.n90.bb.center_x - front.body.bb.center_x == -60 mm, "90 notch 60 left of centre"
    assert len(front.tenons.gap) == 4, "three tenons: four gaps"
    assert len(base.front_mortise.slot) == 3, "three mortises per fence"
}
