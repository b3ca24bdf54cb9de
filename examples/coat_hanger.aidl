# A flat (plywood) coat hanger: a hook on a short neck above a triangular
# body. The body is a thick triangular frame (an outer triangle minus an
# inner one) with a strap notch on each shoulder; the hook is a closed
# outline of two concentric arcs and two end caps, finished with a ball tip.
# Try: --set width=460  --set drop=120  --set bar=18

param width = 420 mm  # shoulder tip to shoulder tip
param drop = 140 mm   # from the apex down to the bottom edge of the bar
param bar = 14 mm     # thickness of the frame
param hook_r = 24 mm  # inner radius of the hook (fits a closet rod)
param neck = 35 mm

wire = 8 mm  # thickness of the hook

# the inner opening is the outer triangle shrunk about its incenter so that
# every side of the frame is `bar` thick
side = sqrt(square(width / 2) + square(drop))
inr = (width * drop / 2) / (side + width / 2)  # inradius of the outer triangle
k = (inr - bar) / inr
iy = -drop + inr  # incenter height (apex at y = 0)

solid hanger {
    solid body {
        frame = Triangle((0, 0), (-width / 2, -drop), (width / 2, -drop))

        hole opening {
            inner = Triangle((0, iy + k * (0 - iy)), (-k * width / 2, iy + k * (-drop - iy)),
                             (k * width / 2, iy + k * (-drop - iy)))
        }
        # the opening follows the frame: centered, `bar` above the bottom (its sides are
        # parallel to the frame's already: both triangles keep the shapes written above)
        opening.bb.bottom == frame.bb.bottom + bar
        AlignCenterX(opening, frame)

        # a strap notch on each shoulder, made by a loop over the two sides
        for s in [-1, 1] {
            hole notch {
                n = Circle(center=(s * 0.38 * width, -0.76 * drop), radius=5)
            }
            OnLine(notch.n.center, frame.ab if s < 0 else frame.ca)
            HorizontalDistance(frame.a, notch.n.center, s * 0.38 * width)
        }
    }

    solid hook {
        c = Point(-hook_r - wire / 2, neck)
        outer = Arc(center=c, radius=hook_r + wire, start_angle=0, end_angle=215)
        inner = Arc(center=c, radius=hook_r, start_angle=0, end_angle=215)
        cap = Line(outer.end, inner.end)
        base = Line(inner.start, outer.start)
        tip = Circle(center=cap.midpoint, radius=0.7 * wire)
        stem = Rectangle(bottom_left=(-wire / 2, -bar), width=wire, height=neck + bar)
    }

    # the neck stands on the apex and reaches into the frame
    Above(hook, body, gap=-bar)
    hook.stem.center.x == body.frame.a.x
}
