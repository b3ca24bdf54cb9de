# Request (home): a child's clothes hanger with the child's name, cut from 6 mm birch ply.
# 320 mm from shoulder tip to shoulder tip. The bottom is a straight trouser bar 15 mm deep
# (y -10 to 5); the top is one arc rising 45 mm from the shoulder tips (y 0 at the tips) to
# the middle. The middle is opened out (a window bounded by the bar's top edge and an arc
# 15 mm under the top arc's apex, its ends 120 mm either side of the centre), leaving a 15 mm
# shoulder band. Two 8 mm round strap notches in the top edge, 140 mm either side of the
# centre. A neck 14 mm wide rises from the apex to a J hook: a 12 mm wide band bent round a
# 32 mm opening (centreline radius 22 mm), turning from the neck up over the top and down the
# far side to 20 deg below the horizontal, round-ended. "MIA" engraved 8 mm high in the middle
# of the bar. Every corner rounded 3 mm so nothing snags the clothes.

units mm
thickness 6 mm

half = 160 mm        # centre to shoulder tip
rise = 45 mm         # top arc: tips to apex
bar_bottom = -10 mm
bar_top = 5 mm
band = 15 mm
neck_w = 14 mm
hook_w = 12 mm
hook_r = 22 mm       # centreline radius of the hook

solid hanger {
    solid shoulders {
        bottom = Line((-half, bar_bottom), (half, bar_bottom))
        right_end = Line((half, bar_bottom), (half, 0))
        top = Arc(start=(half, 0), through=(0, rise), end=(-half, 0))
        left_end = Line((-half, 0), (-half, bar_bottom))
    }

    hole window {
        floor = Line((-120, bar_top), (120, bar_top))
        roof = Arc(start=(120, bar_top), through=(0, rise - band), end=(-120, bar_top))
    }

    hole notch_r {
        c = Circle(center=(140, 12), diameter=8, overrun=true)
    }
    Coincident(notch_r.c.center, shoulders.top)
    notch_r.c.center.x == 140 mm
    notch_l = Mirrored(notch_r, about=Line((0, -20), (0, 80), construction=true))

    solid hook {
        neck = Rectangle(center=(0, rise + 11), width=neck_w, height=24)
        curl = Arc(center=(0, rise + 22 + hook_r), radius=hook_r, start_angle=-20 deg,
                   end_angle=270 deg, construction=true)
        bend = Stroke(curl, width=hook_w)
    }

    drawing name {
        word = Text("MIA", (0, (bar_bottom + bar_top) / 2), size=8, valign="middle")
    }

    Fillet(3)

    assert shoulders.bb.width == 320 mm, "320 mm tip to tip"
    assert shoulders.top.through.y - shoulders.top.start.y == 45 mm, "top rises 45 mm"
    assert bar_top - bar_bottom == 15 mm, "15 mm trouser bar"
    assert shoulders.top.through.y - window.roof.through.y == 15 mm, "15 mm shoulder band"
    assert notch_r.c.diameter == 8 mm, "8 mm strap notches"
    assert 2 * (hook.curl.radius - hook_w / 2) == 32 mm, "32 mm hook opening"
    assert hook.neck.bb.bottom < shoulders.top.through.y, "the neck grows out of the apex"
}
