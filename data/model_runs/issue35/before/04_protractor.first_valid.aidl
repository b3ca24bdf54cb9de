# A protractor: a half-disc of radius 80 mm with tick marks every 10 degrees
# and the angle labels 0..180 engraved.

param R = 80 mm
tick = 8 mm          # tick length, inward from the rim
label_r = R - 16 mm  # radius the labels are centred on

solid protractor {
    disc = Circle(center=(0, 0), radius=R)
    # cut away the lower half: what is left is the half-disc
    hole lower {
        cut = Rectangle(center=(0, -R / 2 - 1), width=2 * R + 4, height=R + 2)
    }
    Fixed(disc)
    AlignCenterX(lower, disc)
    lower.bb.top == disc.center.y

    drawing scale {
        for i in range(19) {
            a = i * 10 deg
            mark = Line((R * cos(a), R * sin(a)), ((R - tick) * cos(a), (R - tick) * sin(a)))
            num = Text(str(i * 10), (label_r * cos(a), label_r * sin(a)), size=4,
                       valign="middle", rotation=a - 90 deg)
        }
        # the centre mark on the straight edge
        centre = Line((0, 0), (0, 6))
    }
    Rigid(scale)
    Coincident(scale.centre.start, disc.center)
}
