# Request (workshop): a set of four cambered glue-up cauls for panel glue-ups, cut from
# 18 mm birch ply. Two are 600 mm long, two 450 mm long, all 45 mm tall at the ends. The
# top edge is straight; the clamping (bottom) edge is a shallow convex arc crowned 2 mm at
# the middle on the long ones and 1.5 mm on the short ones, so clamping the ends presses
# the middle first. Each has a 10 mm hanging hole 20 mm in from its right end at mid-height,
# clamp marks engraved every 100 mm from the middle (8 mm lines down from the top edge,
# not at the ends), and its size engraved in the middle: "600 / CAMBER 2.0" for example.

units mm
thickness 18 mm

H = 45 mm          # height at the ends
HOLE_D = 10 mm
HOLE_IN = 20 mm
TICK = 8 mm
PITCH = 100 mm

def caul(length=600 mm, camber=2 mm) -> solid {
    top = Line((-length / 2, H), (length / 2, H))
    right = Line((length / 2, H), (length / 2, 0))
    face = Arc(start=(length / 2, 0), through=(0, -camber), end=(-length / 2, 0))
    left = Line((-length / 2, 0), (-length / 2, H))
    hole hang {
        c = Circle(center=(length / 2 - HOLE_IN, H / 2), diameter=HOLE_D)
    }
    drawing marks {
        for i in range(-floor((length / 2 - 1 mm) / PITCH), floor((length / 2 - 1 mm) / PITCH) + 1) {
            t = Line((i * PITCH, H), (i * PITCH, H - TICK))
        }
        size = Text(f"{length:.0f} / CAMBER {camber:.1f}", position=(0, H / 2 - 4 mm), size=8,
                    valign="middle")
    }
    Rigid(self)
}

assembly cauls {
    long_a = caul(length=600 mm, camber=2 mm)
    long_b = caul(length=600 mm, camber=2 mm)
    short_a = caul(length=450 mm, camber=1.5 mm)
    short_b = caul(length=450 mm, camber=1.5 mm)

    # laid out in a column for cutting, 6 mm apart
    Below(long_b, long_a, gap=6)
    AlignLeft(long_b, long_a)
    Below(short_a, long_b, gap=6)
    AlignLeft(short_a, long_b)
    Below(short_b, short_a, gap=6)
    AlignLeft(short_b, short_a)

    # the request's numbers
    assert long_a.bb.width == 600 mm, "long cauls are 600 mm"
    assert short_a.bb.width == 450 mm, "short cauls are 450 mm"
    assert long_a.bb.height == 47 mm, "45 mm at the ends + 2 mm crown"
    assert short_a.bb.height == 46.5 mm, "45 mm at the ends + 1.5 mm crown"
    assert long_a.right.length == 45 mm, "45 mm tall at the ends"
    assert long_a.bb.right - long_a.hang.c.center.x == 20 mm, "hanging hole 20 mm from the right end"
    assert len(long_a.marks.t) == 5, "marks at -200 ... 200 on the 600"
    assert len(short_a.marks.t) == 5, "marks at -200 ... 200 on the 450"
}
