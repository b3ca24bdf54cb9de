# Request: a full-size pattern, cut from 3 mm MDF, to trace and pattern-rout a carved portage
# yoke for my 16 ft canoe out of ash. Top view, symmetric about its centre line:
# - 870 mm long overall (gunwale to gunwale plus the overhang), rounded ends about 70 mm wide;
# - two shoulder pads either side of the middle, about 105 mm front to back at 110-130 mm from
#   the centre, tapering to the ends;
# - a neck scoop in the front (bottom) edge: the yoke is 42 mm deep at the centre line;
# - at each end two 8.5 mm holes for the 5/16" hanger bolts, 410 mm from the centre line and
#   30 mm apart front to back;
# - engraved: the centre line (a 20 mm tick at the back and front edge) and "PORTAGE YOKE"
#   and "PATTERN 1:1" in 8 mm letters centred 230 mm left and right of the centre.
# FIX after the first valid program: in the picture the spline overshoots between (330, 36) and
# the end turn (420, 34) -> (435, 0): each end swells into a knob wider than the bar before it,
# a wavy edge a router would copy. More points round the end's turn keep the taper fair.

units mm
thickness 3 mm

solid yoke {
    half = [(0, 30), (110, 46), (210, 40), (320, 36), (395, 34), (426, 24), (435, 0),
            (426, -24), (395, -34), (320, -36), (210, -44), (130, -60), (70, -42), (0, -12)]
    outline = Spline(half, closed=true, mirror="y")

    hole bolts {
        for sx in [-1, 1] {
            for sy in [-1, 1] {
                b = Circle(center=(sx * 410, sy * 15), diameter=8.5)
            }
        }
    }
    drawing marks {
        back_tick = Line((0, 30), (0, 10))
        front_tick = Line((0, -12), (0, 8))
        left = Text("PORTAGE YOKE", position=(-230, 0), size=8, valign="middle")
        right = Text("PATTERN 1:1", position=(230, 0), size=8, valign="middle")
    }

    assert outline.points[6].x - outline.points[-6].x == 870 mm, "870 mm long overall"
    assert outline.points[0].y - outline.points[13].y == 42 mm, "42 mm deep at the neck"
    assert sum([len(r) for r in bolts.b]) == 4, "two bolt holes each end"
    assert bolts.b[1][0].center.x == 410 mm and bolts.b[1][1].center.y - bolts.b[1][0].center.y == 30 mm, "bolts 410 mm out, 30 mm apart"
    assert bolts.b[0][0].diameter == 8.5 mm, "8.5 mm bolt holes"
    assert distance(marks.left, bolts) >= 20 mm, "text clear of the bolts"
}
