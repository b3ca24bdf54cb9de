# Request: a wiggly snake toy cut in place from one piece of 6 mm ply, 347 mm long overall
# (pointed tail to forked tongue tip). The body tapers from a pointed tail (14 mm wide at 20 mm
# from the tip) to 30 mm wide where it meets a 64 x 40 mm oval head. It bends at 9 captive
# ball-and-socket joints every 25 mm (10 links): each a 9 mm ball on a 4 mm neck, cut as one
# zero-width line from edge to edge, the laser's kerf its play. Two 4 mm eye holes 16 mm apart,
# a forked tongue 2 mm wide, and an engraved diamond (8 x 6 mm) on the back of each link.

units mm
thickness 6 mm

N_JOINTS = 9
PITCH = 25 mm
BALL_R = 4.5 mm
BALL_C = 6 mm          # the ball's centre, past the joint line
NECK = 4 mm
def half(x) = 7 mm + x * 8 / 260     # half the body's width at x (tail end at x = 0)
NECK_X = BALL_C - sqrt(BALL_R ** 2 - (NECK / 2) ** 2)   # where the neck meets the ball
BALL_A = 180 deg - asin(NECK / 2 / BALL_R)              # the ball's arc, from -BALL_A to BALL_A

solid snake {
    body = Polygon([(-20, 0), (0, 7), (260, 15), (260, -15), (0, -7)])
    head = Ellipse(center=(280, 0), rx=32, ry=20)
    tongue = Polygon([(310, 1), (322, 1), (327, 4), (323.5, 0), (327, -4), (322, -1), (310, -1)])
    hole eyes {
        l = Circle(center=(288, 8), diameter=4)
        r = Circle(center=(288, -8), diameter=4)
    }
    cut joints {
        for j in range(N_JOINTS) {
            x0 = PITCH * (j + 1)
            down = Line((x0, half(x0)), (x0, NECK / 2))
            neck_top = Line((x0, NECK / 2), (x0 + NECK_X, NECK / 2))
            ball = Arc(center=(x0 + BALL_C, 0), radius=BALL_R, start_angle=-BALL_A,
                       end_angle=BALL_A)
            neck_bot = Line((x0 + NECK_X, -NECK / 2), (x0, -NECK / 2))
            up = Line((x0, -NECK / 2), (x0, -half(x0)))
            over_top = Line((x0, half(x0)), (x0, half(x0) + 1), overrun=true)
            over_bot = Line((x0, -half(x0)), (x0, -half(x0) - 1), overrun=true)
        }
    }
    drawing scales {
        for k in range(N_JOINTS + 1) {
            cx = 5 mm if k == 0 else PITCH * k + 17.5 mm
            d = Polygon([(cx - 4, 0), (cx, 3), (cx + 4, 0), (cx, -3)])
        }
    }

    # the request's numbers
    assert self.bb.width == 347 mm, "347 mm overall"
    assert head.bb.width == 64 mm and head.bb.height == 40 mm, "64 x 40 head"
    assert len(joints.ball) == 9, "9 joints: 10 links"
    assert joints.ball[1].center.x - joints.ball[0].center.x == 25 mm, "a joint every 25 mm"
    assert joints.ball[0].radius * 2 == 9 mm, "9 mm balls"
    assert joints.neck_top[0].start.y - joints.neck_bot[0].end.y == 4 mm, "4 mm necks"
    assert eyes.l.diameter == 4 mm and eyes.l.center.y - eyes.r.center.y == 16 mm, "eyes"
    assert len(scales.d) == 10, "a diamond per link"
    assert half(PITCH) - BALL_R >= 3 mm, "3 mm of wood beside the first ball"
}
