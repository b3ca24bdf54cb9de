# The studio's form of examples/generators/dovetail.aidl: its arguments as params whose
# ranges follow each other (docs/studio.md, "Forms that cannot fail").
import "std/joints.aidl"

# The tails widen at `angle` over `depth`: the steeper and deeper, the wider their tips, so
# the angle's range follows the pitch (length / tails) and the depth: tan(angle) at most 0.6
# of (pitch / 4) / (depth / 2 + 1 mm), the generator's own limit with room for the
# clearance; a pitch of at least 12 mm.
param length = 90 mm, min = 24 mm, max = 400 mm, step = 1 mm
param tails = 3, min = 1, max = max(1, min(12, floor(length / 12 mm))), step = 1
param depth = 10 mm, min = 2 mm, max = 25 mm, step = 0.5 mm
param angle = 10 deg, min = 0 deg, max = min(20 deg, atan(0.6 * length / tails / 4 / (depth / 2 + 1 mm))), step = 0.5 deg
param clearance = 0 mm, min = 0 mm, max = 0.5 mm, step = 0.05 mm

thickness 3 mm

assembly board {
    solid lower {
        body = Rectangle(center=(0, 0), width=length, height=50)  # up to the tips: y 25
        tails = dovetail(part="tail", length=length, depth=depth, tails=tails, angle=angle,
                         clearance=clearance, cy=25 mm - depth)
    }
    solid upper {
        body = Rectangle(center=(0, 50), width=length, height=40)  # from the line: y 30
        sockets = dovetail(part="socket", length=length, depth=depth, tails=tails, angle=angle,
                           clearance=clearance, cy=30 mm)
    }
    # assembled in the sheet's plane: the upper panel slid down onto the tails
    Place(upper, position=(0, -(5 mm + depth), 0))
}
