# Request: a lift-up starting gate for four 1:64 die-cast cars on a wooden ramp 200 mm
# wide with four lanes at 45 mm pitch, in 6 mm birch ply. Two posts 60 mm wide and
# 120 mm tall are screwed to the ramp's side faces (their lower 40 mm on the ramp side,
# two 4.5 mm holes countersunk 9 mm, 20 mm below the ramp surface, 36 mm apart); each has
# a 6.5 mm notch open at the top, centred, down to 30 mm above the ramp surface. The gate
# spans the ramp: a bar 45 mm tall between the posts (0.5 mm clear of each) whose 12.5 mm
# end tongues, 40 mm tall, ride in the notches and rest on their bottoms; its bar reaches
# 5 mm lower than the tongues inside the posts so it cannot slide sideways out. Four
# fingers 20 mm wide hang from the bar, one on each lane's centre line, ending 2 mm above
# the ramp (tips rounded R3). On top, a half-disc handle R25 with a 30 x 12 finger slot.
# The lane numbers 1-4 are engraved on the bar above the fingers, 10 mm tall.
# Lifting the gate 35 mm lets the cars (30 mm tall) run under; the tongues stay 15 mm
# in the notches.

t = 6 mm
thickness t

RAMP_W = 200 mm
PITCH = 45 mm
LANES = 4
NOTCH_BOT = 30 mm        # above the ramp surface
POST_TOP = 80 mm
POST_BELOW = 40 mm
def lane_x(i) = (i - (LANES - 1) / 2) * PITCH

def post() -> solid {
    # x: along the lane, y: up, 0 at the ramp surface
    body = Rectangle(corner=(-30, -POST_BELOW), opposite=(30, POST_TOP))
    hole notch {
        n = Rectangle(corner=(-3.25, NOTCH_BOT), opposite=(3.25, POST_TOP + 1))
    }
    hole screws {
        s1 = Circle(center=(-18, -20), diameter=4.5)
        s2 = Circle(center=(18, -20), diameter=4.5)
    }
    Countersink(screws, diameter=9)
}

assembly start_gate {
    left_post = post()
    right_post = post()

    solid gate {
        # x: across the ramp, 0 on its centre line; y: up, 0 at the ramp surface
        bar = Rectangle(corner=(-(RAMP_W / 2 - 0.5), NOTCH_BOT - 5),
                        opposite=(RAMP_W / 2 - 0.5, NOTCH_BOT + 40))
        # FIX after the first valid program: the bar was 50 tall (25..75), the request says 45
        tongue_l = Rectangle(corner=(-(RAMP_W / 2 + t + 6.5), NOTCH_BOT),
                             opposite=(-(RAMP_W / 2 - 1), NOTCH_BOT + 40))
        tongue_r = Rectangle(corner=(RAMP_W / 2 - 1, NOTCH_BOT),
                             opposite=(RAMP_W / 2 + t + 6.5, NOTCH_BOT + 40))
        for i in range(LANES) {
            f = Rectangle(corner=(lane_x(i) - 10, 2), opposite=(lane_x(i) + 10, NOTCH_BOT - 4))
            Fillet(f.bottom_left, 3)
            Fillet(f.bottom_right, 3)
        }
        handle = Sector(center=(0, NOTCH_BOT + 40), radius=25, start_angle=0, end_angle=180)
        hole grip {
            s = Slot(center=(0, NOTCH_BOT + 50), length=30, width=12)
        }
        drawing numbers {
            for i in range(LANES) {
                n = Text(str(i + 1), position=(lane_x(i), NOTCH_BOT + 15), size=10,
                         valign="middle")
            }
        }
    }

    # flat on the sheet
    Below(left_post, gate, gap=10)
    AlignLeft(left_post, gate)
    RightOf(right_post, left_post, gap=10)
    AlignTop(right_post, left_post)

    # in 3D: x across the ramp, y down the lanes, z up from the ramp surface
    Place(gate, position=(0, t / 2, 0), face="front", up="up")
    Place(left_post, position=(-RAMP_W / 2, 0, 0), face="left", up="up")
    Place(right_post, position=(RAMP_W / 2, 0, 0), face="right", up="up")

    assert len(gate.f) == 4, "four fingers"
    assert gate.f[1].center.x - gate.f[0].center.x == 45 mm, "lanes 45 apart"
    assert gate.f[0].width == 20 mm, "fingers 20 wide"
    assert gate.tongue_l.bb.bottom - gate.f[0].bb.bottom == 28 mm,
        "fingers end 2 above the ramp when the tongues sit 30 up"
    assert left_post.notch.n.bb.bottom - (left_post.body.bb.bottom + 40 mm) == 30 mm,
        "notch bottom 30 above the ramp surface"
    assert left_post.body.bb.height == 120 mm and left_post.body.bb.width == 60 mm,
        "posts 60 x 120"
    assert gate.bar.bb.width == 199 mm, "0.5 clear of each post"
    assert gate.tongue_l.bb.height == 40 mm, "tongues 40 tall"
    assert gate.bar.bb.height == 45 mm, "bar 45 tall"
    assert gate.tongue_l.bb.bottom - gate.bar.bb.bottom == 5 mm, "bar 5 lower than the tongues"
    assert left_post.notch.n.bb.width == 6.5 mm, "6.5 notch"
    assert POST_TOP - NOTCH_BOT - 35 mm >= 15 mm, "15 mm still engaged when lifted 35"
    assert gate.handle.radius == 25 mm, "R25 handle"
    assert distance(left_post.screws.s1.center, left_post.screws.s2.center) == 36 mm,
        "screws 36 apart"
}
