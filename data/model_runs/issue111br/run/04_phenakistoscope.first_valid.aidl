# Request: a phenakistoscope (the Victorian spinning-disc animation toy), 3 mm plywood. A 250 mm
# disc with 12 radial viewing slits, 3 mm wide and 30 mm long, centred on a 105 mm radius,
# evenly round; between each two slits one frame of a bouncing ball engraved (a short ground
# arc at 40 mm radius, the ball 12 mm across, filled, rising up to 35 mm off the ground
# and back, squashed flat on the ground in the first frame), "PHENAKISTOSCOPE" engraved round a
# 26 mm radius circle in the middle, and a 5.5 mm hole for the M5 axle bolt. A 300 x 24 mm
# handle with round ends and a 5.5 mm hole 12 mm from its top end, and a 16 mm spacer washer
# between disc and handle so the disc spins free. Spin it facing a mirror and look through
# the slits.

units mm
thickness 3 mm

import "std/shapes.aidl"

N = 12
R_DISC = 125 mm
R_SLIT = 105 mm
R_GROUND = 40 mm
BALL_D = 12 mm
BOUNCE = 35 mm
HANDLE_L = 300 mm
AXLE_D = 5.5 mm

def slit_angle(k) = k * 360 deg / N
def frame_angle(k) = (k + 0.5) * 360 deg / N
# the ball's centre, its distance from the disc's centre in frame k
def ball_r(k) = R_GROUND + BALL_D / 2 + BOUNCE * sin(k * 180 deg / N)

assembly toy {
    solid disc {
        body = Circle(center=(0, 0), radius=R_DISC)
        hole axle { c = Circle(center=(0, 0), diameter=AXLE_D) }
        hole slits {
            for k in range(N) {
                s = Slot(center=(R_SLIT * cos(slit_angle(k)), R_SLIT * sin(slit_angle(k))),
                         length=30, width=3, rotation=slit_angle(k))
            }
        }
        drawing frames {
            for k in range(N) {
                ground = Arc(center=(0, 0), radius=R_GROUND, start_angle=frame_angle(k) - 8 deg,
                             end_angle=frame_angle(k) + 8 deg)
            }
            # frame 0: the ball squashed on the ground (its radial axis short)
            squash = Ellipse(center=((R_GROUND + 4.5 mm) * cos(frame_angle(0)),
                                     (R_GROUND + 4.5 mm) * sin(frame_angle(0))),
                             rx=4.5, ry=7.5, rotation=frame_angle(0), fill=true)
            for k in range(1, N) {
                ball = Circle(center=(ball_r(k) * cos(frame_angle(k)),
                                      ball_r(k) * sin(frame_angle(k))),
                              diameter=BALL_D, fill=true)
            }
        }
        drawing title {
            ring = Circle(center=(0, 0), radius=26, construction=true)
            t = Text("PHENAKISTOSCOPE", along=ring, size=5)
        }
    }

    solid handle {
        stick = Slot(center=(0, 0), length=HANDLE_L, width=24, rotation=90)
        hole axle { c = Circle(center=(0, HANDLE_L / 2 - 12 mm), diameter=AXLE_D) }
    }

    spacer = washer(outer=16 mm, inner=AXLE_D)

    # 3D: the handle flat, the washer on its hole, the disc on the washer
    Place(handle, position=(0, 0, 0))
    Place(spacer, position=(0, HANDLE_L / 2 - 12 mm, 3))
    Place(disc, position=(0, HANDLE_L / 2 - 12 mm, 6))

    # the sheet
    RightOf(handle, disc, gap=5)
    AlignCenterY(handle, disc)
    RightOf(spacer, handle, gap=5)
    AlignCenterY(spacer, handle)

    # the request's numbers
    assert disc.body.diameter == 250 mm, "250 mm disc"
    assert len(disc.slits.s) == 12, "12 slits"
    assert disc.slits.s[0].length == 30 mm and disc.slits.s[0].width == 3 mm, "slits 3 x 30"
    assert len(disc.frames.ground) == 12 and len(disc.frames.ball) == 11, "12 frames"
    assert abs(norm(disc.slits.s[3].center) - 105 mm) < 0.001 mm, "slits on r105"
    assert max([ball_r(k) for k in range(N)]) - BALL_D / 2 - R_GROUND <= 35 mm, "bounce 35"
    assert handle.stick.length == 300 mm and handle.stick.width == 24 mm, "handle 300 x 24"
    assert handle.stick.bb.top - handle.axle.c.center.y == 12 mm, "hole 12 from the top"
    assert R_SLIT - 15 mm - (max([ball_r(k) for k in range(N)]) + BALL_D / 2) >= 3 mm,
        "the highest ball clears the slits"
}
