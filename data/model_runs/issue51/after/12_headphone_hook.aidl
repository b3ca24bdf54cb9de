# Headphone hook that screws under a desk: a J-shaped profile about 60 x 90 mm.
# A flat top flange (screwed to the desk's underside) carries two holes for
# 4 mm countersunk screws; a 12 mm wide stem runs down into a J that holds
# the headband. The countersinks are marked by an engraved ring (head size).

import "std/fasteners.aidl"

param flange_w = 60 mm
param flange_h = 16 mm
param height = 90 mm
param bar = 12 mm
param cup_r = 18 mm        # radius of the J's centre line
param lip = 12 mm          # how far the J's tip rises above the cup centre
param screw_pitch = 40 mm
param head_d = 8 mm        # countersunk head diameter of an M4 screw

solid hook {
    flange = Rectangle(center=(0, height - flange_h / 2), width=flange_w, height=flange_h)
    Fixed(flange)

    # the J: stem down the left, round cup at the bottom, short tip on the right
    stem = Line((-cup_r, height - flange_h / 2), (-cup_r, bar / 2 + cup_r))
    cup = Arc(center=(0, bar / 2 + cup_r), radius=cup_r, start_angle=180 deg, end_angle=360 deg)
    tip = Line((cup_r, bar / 2 + cup_r), (cup_r, bar / 2 + cup_r + lip))
    j = Stroke([stem, cup, tip], width=bar)

    left_screw = clearance_hole(size=4)
    right_screw = clearance_hole(size=4)
    AlignCenterY(left_screw, flange)
    AlignCenterY(right_screw, flange)
    HorizontalDistance(left_screw.c.center, right_screw.c.center, screw_pitch)
    (left_screw.c.center.x + right_screw.c.center.x) / 2 == flange.center.x

    drawing countersinks {
        ring_l = Circle(center=(-screw_pitch / 2, height - flange_h / 2), diameter=head_d)
        ring_r = Circle(center=(screw_pitch / 2, height - flange_h / 2), diameter=head_d)
    }
    Concentric(countersinks.ring_l, left_screw.c)
    Concentric(countersinks.ring_r, right_screw.c)
}
