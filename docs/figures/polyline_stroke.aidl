# Figure of docs/language.md: an open Polyline engraved as a zig-zag on a tag, a Polyline
# path and an S of two tangent arcs made into bands by Stroke (round and flat ends).
# Drawn by `python docs/make_pictures.py` to docs/images/polyline_stroke.png.

assembly strokes {
    solid tag {
        body = RoundedRectangle(center=(0, 0), width=40, height=20, corner_radius=3)
        Fixed(body)
        drawing zigzag {
            z = Polyline([(-15, -5), (-10, 5), (-5, -5), (0, 5), (5, -5), (10, 5), (15, -5)])
        }
        Coincident(zigzag.z.start, (-15, -5))
    }
    solid wire {
        p = Polyline([(30, -8), (45, -8), (55, 8), (70, 8)])
        band = Stroke(p, width=4)
    }
    solid hook {
        top = Arc(center=(85, 6), radius=6, start_angle=-90 deg, end_angle=90 deg)
        bottom = Arc(center=(85, -6), radius=6, start_angle=90 deg, end_angle=270 deg)
        band = Stroke([top, bottom], width=3, cap="flat")
    }
}
