# A wall key holder: a 150 x 50 mm board with five evenly spaced keyhole
# slots and two screw holes for fixing it to the wall.

param width = 150 mm
param height = 50 mm
param slots = 5
param head_d = 9 mm      # the round entry of a keyhole
param neck_w = 4.5 mm    # the narrow slot the screw head hangs in
param neck_len = 12 mm
param screw_d = 4.5 mm

pitch = width / (slots + 1)

def keyhole() -> hole {
    entry = Circle(center=(0, 0), diameter=head_d)
    neck = Slot(start=(0, 0), length=neck_len, angle=90 deg, width=neck_w)
    Coincident(neck.start, entry.center)
}

solid board {
    plate = RoundedRectangle(center=(0, 0), width=width, height=height, corner_radius=4)
    Fixed(plate)

    first = keyhole()
    row = LinearPattern(first, slots, (pitch, 0))
    HorizontalDistance(plate.left.midpoint, first.entry.center, pitch)
    VerticalDistance(plate.center, first.entry.center, -6 mm)

    hole screw_l {
        s = Circle(center=(-width / 2 + 8, height / 2 - 8), diameter=screw_d)
    }
    hole screw_r {
        s = Circle(center=(width / 2 - 8, height / 2 - 8), diameter=screw_d)
    }
    At(screw_l.s.center, plate.top_left, dx=8, dy=-8)
    At(screw_r.s.center, plate.top_right, dx=-8, dy=-8)
}
