# Request (crafts): a sit-on embroidery hoop stand, 6 mm birch ply. A 250 x 120 mm paddle
# (20 mm corner radii) you sit on, with a 12 x 60 mm slot to drop small snips into, 40 mm from
# its left end. An upright, 50 mm wide, standing 300 mm above the paddle with a round top, glued
# into the paddle 80 mm right of its centre by two 12 mm tabs in mortises (0.1 mm clearance);
# up the upright runs a 6.6 mm slot for an M6 bolt, from 120 mm to 270 mm up. An arm 200 mm
# long and 40 mm wide with round ends and two M6 holes 160 mm apart pivots on that bolt with
# a wing nut; "STITCH" is engraved on it in filled 10 mm letters. At the arm's far end a
# 60 x 40 mm clamp plate (8 mm radii) with an M6 hole 15 mm left of its middle pinches the
# hoop's outer ring (8 mm) against the arm with a second bolt and wing nut.

units mm
thickness 6 mm
import "std/joints.aidl"
import "std/fasteners.aidl"

t = 6 mm
paddle_l = 250 mm
paddle_w = 120 mm
post_w = 50 mm
post_h = 300 mm
post_x = 80 mm
slot_lo = 120 mm
slot_hi = 270 mm
arm_pitch = 160 mm
arm_w = 40 mm
pivot_z = t + 200 mm      # where the arm is shown: 200 mm up the upright
ring = 8 mm

assembly hoop_stand {
    solid paddle {
        body = RoundedRectangle(center=(0, 0), width=paddle_l, height=paddle_w, corner_radius=20)
        mortise = tab_and_slot(part="slot", length=post_w, thickness=t, tabs=2, tab=12,
                               screw=0, clearance=0.1 mm, cx=post_x, cy=0)
        hole snips { s = Slot(center=(-paddle_l / 2 + 40 + 6, 0), length=60, width=12,
                              rotation=90 deg) }
    }
    solid upright {
        body = RoundedRectangle(bottom_left=(-post_w / 2, -t), width=post_w, height=post_h + t,
                                corner_radii=[post_w / 2, post_w / 2, 0, 0])
        tabs = tab_and_slot(part="tab", length=post_w, thickness=t, tabs=2, tab=12, screw=0,
                            rotation=180 deg, cx=0, cy=-t)
        hole track { s = Slot(start=(0, slot_lo), end=(0, slot_hi), width=6.6) }
    }
    solid arm {
        body = Slot(start=(-arm_pitch, 0), end=(0, 0), width=arm_w)
        pivot = clearance_hole(size=6, cx=0, cy=0)
        hoop_end = clearance_hole(size=6, cx=-arm_pitch, cy=0)
        drawing name {
            w = Text("STITCH", position=(-arm_pitch / 2, 0), size=10, font="sans:Bold",
                     fill=true, valign="middle")
        }
    }
    solid clamp {
        body = RoundedRectangle(center=(0, 0), width=60, height=40, corner_radius=8)
        bolt = clearance_hole(size=6, cx=-15, cy=0)
    }

    # on the sheet
    RightOf(upright, paddle, gap=10)
    Above(arm, paddle, gap=10)
    AlignLeft(arm, paddle)
    Below(clamp, paddle, gap=10)
    AlignLeft(clamp, paddle)

    # assembled: the paddle flat, the upright in the plane y = 0 on its mortises, the arm
    # bolted on the upright's front face pointing back over the paddle, the clamp plate one
    # hoop ring further out
    Place(paddle, position=(0, 0, 0))
    Place(upright, position=(post_x, t / 2, t), face="front", up="up")
    Place(arm, position=(post_x, -t / 2, pivot_z), face="front", up="up")
    Place(clamp, position=(post_x - arm_pitch + 15, -t / 2 - t - ring, pivot_z), face="front",
          up="up")

    assert paddle.body.bb.width == 250 mm and paddle.body.bb.height == 120 mm, "paddle 250 x 120"
    assert paddle.snips.s.width == 12 mm and paddle.snips.s.length == 60 mm, "snips slot 12 x 60"
    assert paddle.snips.bb.left - paddle.body.bb.left == 40 mm, "snips slot 40 mm from the end"
    assert upright.body.bb.top - (upright.body.bb.bottom + t) == 300 mm, "upright 300 mm above"
    assert upright.body.bb.width == 50 mm, "upright 50 mm wide"
    assert upright.track.s.start.y == 120 mm and upright.track.s.end.y == 270 mm,
        "bolt travels 120 to 270 mm up"
    assert paddle.mortise.slot[0].bb.center_x + paddle.mortise.slot[1].bb.center_x == 2 * 80 mm,
        "upright 80 mm right of the centre"
    assert arm.body.bb.width == 200 mm and arm.body.bb.height == 40 mm, "arm 200 x 40"
    assert arm.pivot.c.center.x - arm.hoop_end.c.center.x == 160 mm, "arm holes 160 mm apart"
    assert clamp.body.bb.width == 60 mm and clamp.body.bb.height == 40 mm, "clamp 60 x 40"
    assert clamp.body.bb.center_x - clamp.bolt.c.center.x == 15 mm, "clamp hole 15 mm left"
}
