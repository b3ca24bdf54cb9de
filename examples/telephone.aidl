# An old-school desk telephone, front view: a trapezoid base on two feet with
# a rotary dial (10 finger holes cut in a loop, numbers engraved beside
# them, a finger stop), a two-pronged cradle, the handset resting on it with
# an earpiece cup and a mouthpiece cup, and a coiled cord (a drawing beside the
# part, so the assembly holds both).
# Try: --set base_w=180  --set dial_r=38  --set handset_len=190

param base_w = 160 mm  # width of the base at the bottom
param base_h = 90 mm
param dial_r = 34 mm
param handset_len = 170 mm

top_w = 0.7 * base_w              # the base narrows toward the top
hole_r = 5.5 mm                   # finger holes
ring_r = 0.72 * dial_r            # finger holes sit on this circle
digit_r = ring_r - hole_r - 3 mm  # digits sit inside the ring of holes
dial_y = 0.48 * base_h
prong_h = 16 mm
grip_h = 12 mm
grip_y = base_h + prong_h + grip_h / 2
cup_x = handset_len / 2 - 15 mm

assembly desk {
    solid telephone {
        solid base {
            body = Polygon([(-base_w / 2, 0), (base_w / 2, 0), (top_w / 2, base_h), (-top_w / 2, base_h)])
            for s in [-1, 1] {
                foot = RoundedRectangle(center=(s * 0.38 * base_w, -2), width=22, height=6, corner_radius=2)
            }

            # the dial's finger holes: digit 1 at 30 degrees, then counter-clockwise to 0
            hole finger_holes {
                pitch = Circle(center=(0, dial_y), radius=ring_r, construction=true)
                for k in range(10) {
                    a = 30 deg + k * 30 deg
                    h = Circle(center=(ring_r * cos(a), dial_y + ring_r * sin(a)), radius=hole_r)
                    OnCircle(h.center, pitch)
                }
            }

            drawing dial {
                rim = Circle(center=(0, dial_y), radius=dial_r)
                hub = Circle(center=(0, dial_y), radius=0.38 * dial_r)
                # the digits inside the ring of holes, each beside its hole
                for k in range(10) {
                    a = 30 deg + k * 30 deg
                    digit = Text(str((k + 1) % 10), (digit_r * cos(a), dial_y + digit_r * sin(a) - 2 mm),
                                 size=4)
                }
                # the finger stop, just past the 0 at about four o'clock
                stop = Line((0.8 * dial_r * cos(-30 deg), dial_y + 0.8 * dial_r * sin(-30 deg)),
                            (1.1 * dial_r * cos(-30 deg), dial_y + 1.1 * dial_r * sin(-30 deg)))
                number = Text("TEL", (0, dial_y - 2 mm), size=5)
            }

            # the dial is centered on the base, holes concentric with its rim
            Concentric(finger_holes.pitch, dial.rim)
            dial.rim.center.x == body.center.x
            dial.rim.center.y == body.bb.bottom + dial_y
        }

        solid cradle {
            for s in [-1, 1] {
                prong = Rectangle(center=(s * 0.24 * base_w, base_h + prong_h / 2), width=8, height=prong_h)
            }
            AlignBottom(prong[0], prong[1])
        }

        solid handset {
            grip = RoundedRectangle(center=(0, grip_y), width=handset_len, height=grip_h,
                                    corner_radius=grip_h / 2)
            # two cups hanging under the grip: half discs, each an arc closed by a line
            ear = Arc(center=(-cup_x, grip_y), radius=17, start_angle=180, end_angle=360)
            ear_top = Line(ear.end, ear.start)
            mouth = Arc(center=(cup_x, grip_y), radius=19, start_angle=180, end_angle=360)
            mouth_top = Line(mouth.end, mouth.start)
            Horizontal(ear.center, mouth.center)
            ear.center.y == grip.center.y
            HorizontalDistance(ear.center, mouth.center, 2 * cup_x)
        }

        # stack: cradle on the base, the handset's grip resting on the prongs
        Above(cradle, base)
        AlignCenterX(cradle, base)
        handset.grip.bb.bottom == cradle.bb.top
        AlignCenterX(handset.grip, base.body)
    }

    # a coiled cord from the earpiece end down to the base
    drawing cord {
        for i in range(14) {
            coil = Circle(center=(-base_w / 2 - 20, grip_y - 12 - i * 5 mm), radius=5)
        }
        lead_in = Line((-cup_x - 17, grip_y), (-base_w / 2 - 20, grip_y - 7))
        lead_out = Line((-base_w / 2 - 20, grip_y - 12 - 13 * 5 mm - 5), (-base_w / 2 + 2, 12))
    }
    Coincident(cord.lead_in.start, telephone.handset.ear.start)
}
