# Request (pets): a freestanding pet gate for a doorway, 6 mm birch ply, cut on a 600 x 400 mm
# bed. The gate is 760 mm wide and 500 mm tall, in two 380 mm halves joined edge to edge up the
# middle by a sliding dovetail (3 tails, 20 mm deep, 0.2 mm clearance). Each half has six
# see-through openings 25 mm wide and 300 mm tall at 50 mm pitch, kept at least 50 mm from its
# edges, and an 80 mm top rail with stencil-cut letters: "GOOD" on the left, "DOG" on the right.
# The outer top corners are rounded, 30 mm. Two feet, 300 mm long and 120 mm tall, tapering to
# 80 mm at the top, cross-halve onto the gate's bottom edge 60 mm in from each end.

units mm
thickness 6 mm
import "std/joints.aidl"

t = 6 mm
half_w = 380 mm
gate_h = 500 mm
dt_depth = 20 mm
fit = 0.2 mm
open_w = 25 mm
open_h = 300 mm
open_pitch = 50 mm
opens = 6
open_y = 120 mm + open_h / 2
rail = 80 mm
foot_l = 300 mm
foot_h = 120 mm
foot_top = 80 mm
foot_x = half_w - 60 mm

def foot() -> solid {
    body = Polygon([(-foot_l / 2, 0), (foot_l / 2, 0), (foot_l / 2, 20), (foot_top / 2, foot_h),
                    (-foot_top / 2, foot_h), (-foot_l / 2, 20)])
    slot = cross_halving(depth=foot_h / 2, thickness=t, clearance=fit, cx=0, cy=foot_h)
}

assembly gate {
    solid left_half {
        body = RoundedRectangle(bottom_left=(-half_w, 0), width=half_w + dt_depth, height=gate_h,
                                corner_radii=[30, 0, 0, 0])
        joint = dovetail(part="tail", length=gate_h, depth=dt_depth, tails=3,
                         rotation=-90 deg, cx=0, cy=gate_h / 2)
        for k in range(opens) {
            hole bar { s = Slot(center=(-65 - k * open_pitch, open_y), length=open_h,
                                width=open_w, rotation=90 deg) }
        }
        hole word { w = Text("GOOD", position=(-half_w / 2, gate_h - rail / 2), size=40,
                             font="sans:Bold", stencil=true, valign="middle") }
        foot_slot = cross_halving(depth=foot_h / 2, thickness=t, clearance=fit, cx=-foot_x,
                                  cy=0, rotation=180 deg)
    }
    solid right_half {
        body = RoundedRectangle(bottom_left=(0, 0), width=half_w, height=gate_h,
                                corner_radii=[0, 30, 0, 0])
        joint = dovetail(part="socket", length=gate_h, depth=dt_depth, tails=3,
                         clearance=fit, rotation=-90 deg, cx=0, cy=gate_h / 2)
        for k in range(opens) {
            hole bar { s = Slot(center=(65 + k * open_pitch, open_y), length=open_h,
                                width=open_w, rotation=90 deg) }
        }
        hole word { w = Text("DOG", position=(half_w / 2, gate_h - rail / 2), size=40,
                             font="sans:Bold", stencil=true, valign="middle") }
        foot_slot = cross_halving(depth=foot_h / 2, thickness=t, clearance=fit, cx=foot_x,
                                  cy=0, rotation=180 deg)
    }
    for s in [-1, 1] {
        f = foot()
        Place(f, position=(s * foot_x - t / 2, 0, 0), face="right", up="up")
    }
    Below(f[0], left_half, gap=20)
    AlignLeft(f[0], left_half)
    RightOf(f[1], f[0], gap=20)
    AlignCenterY(f[1], f[0])

    # both halves stand in the plane y = 0, their drawings' y up
    Place(left_half, position=(0, t / 2, 0), face="front", up="up")
    Place(right_half, position=(0, t / 2, 0), face="front", up="up")

    assert right_half.body.bb.right - left_half.body.bb.left == 760 mm, "gate 760 mm wide"
    assert left_half.body.bb.height == 500 mm, "gate 500 mm tall"
    assert right_half.body.bb.width == 380 mm, "380 mm halves"
    assert left_half.body.bb.width - dt_depth == 380 mm, "380 mm halves (left, less its tails)"
    assert len(left_half.bar) == 6 and len(right_half.bar) == 6, "six openings each"
    assert left_half.bar[0].s.width == 25 mm and left_half.bar[0].s.length == 300 mm,
        "openings 25 x 300"
    assert left_half.bar[0].bb.left - left_half.bar[1].bb.left == 50 mm, "50 mm pitch"
    assert left_half.bar[5].bb.left - left_half.body.bb.left >= 50 mm, "50 mm from the outer edge"
    assert 0 - left_half.bar[0].bb.right >= 50 mm, "50 mm from the joint"
    assert gate_h - left_half.bar[0].bb.top == 80 mm, "80 mm top rail"
    assert f[0].body.bb.width == 300 mm and f[0].body.bb.height == 120 mm, "feet 300 x 120"
    assert half_w - foot_x == 60 mm, "feet 60 mm in from the ends"
}
