# Request: a clamp-on bag hook for the edge of my office desk (top 25 mm thick), cut from
# 6 mm acrylic twice and glued back to back (12 mm thick).
# - Profile seen from the side: an 18 mm wide band. An inverted U slides over the desk edge:
#   a top arm lying 60 mm onto the desk, a gap of 26 mm (1 mm play on the 25 mm top),
#   an arm 40 mm under the desk. From the U's front leg the band drops to 110 mm below the
#   desk top and curls into a hook with a 15 mm inner radius, its tip turned up 30 deg.
# - "ANNA" engraved (bold, 9 mm, filled) up the front leg of the outer layer.

thickness 6 mm

W = 18 mm        # band width
GAP = 26 mm      # the U's opening
R_IN = 15 mm     # the hook's inner radius
DROP = 110 mm    # where the curl starts, below the desk top

def profile() -> solid {
    # the desk's front edge is x = 0, its top y = 0; the desk lies toward -x
    top = Line((-60, W / 2), (W / 2, W / 2))
    leg = Line((W / 2, W / 2), (W / 2, -DROP))
    curl = Arc(center=(W / 2 + R_IN + W / 2, -DROP), radius=R_IN + W / 2,
               start_angle=180 deg, end_angle=30 deg)
    band = Stroke([top, leg, curl], width=W)
    low = Line((W / 2, -GAP - W / 2), (-40, -GAP - W / 2))
    under = Stroke(low, width=W)
}

assembly bag_hook {
    outer = profile()
    inner = profile()

    drawing name {
        t = Text("ANNA", position=(W / 2, -60), size=9, font="sans:Bold", fill=true,
                 rotation=90 deg, valign="middle")
    }
    CutInto(name, outer)

    RightOf(inner, outer, gap=10)
    AlignTop(inner, outer)

    # glued back to back, the engraved face to the front
    Place(outer, position=(0, 0, 0), face="front", up="up")
    Place(inner, position=(0, 6, 0), face="front", up="up")

    # the request's numbers
    assert (outer.top.start.y - W / 2) - (outer.low.start.y + W / 2) == 26 mm,
        "U opening 26 mm"
    assert outer.curl.radius - W / 2 == 15 mm, "hook inner radius 15"
    assert outer.top.end.x - outer.top.start.x == 60 mm + W / 2, "top arm 60 onto the desk"
    assert outer.low.start.x - outer.low.end.x == 40 mm + W / 2, "lower arm 40 under the desk"
    assert outer.leg.end.y == -110 mm, "curl starts 110 below the desk top"
}
