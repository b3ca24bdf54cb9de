# Request: an orienteering compass baseplate in 3 mm clear acrylic, 66 x 120 mm with R6
# corners, for a 40 mm liquid-filled button compass glued into a 40 mm round hole on the
# centre line, its centre 15 mm below the plate's centre. A direction-of-travel arrow
# engraved filled above it, 47 mm long (tip 55 mm above the plate's centre), head 16 mm
# wide, shaft 4 mm. Two engraved orienting lines 24 mm apart beside the arrow. A ruler
# down the left edge: 0-11 cm, ticks every 1 mm (3 mm long, 5 mm at 5 mm, 7 mm at each cm)
# with the cm numbered, 2.5 mm figures. A 1:50 000 map scale down the right edge: 0-5 km,
# ticks every 100 m (2 mm), 7 mm at each km, numbered; "1:50 000" engraved at its foot
# (FIX after the first valid program: at its top end, see below). A
# 4 mm lanyard hole on the centre line 10 mm above the bottom edge.

units mm
thickness 3 mm

plate_w = 66 mm
plate_h = 120 mm
edge_l = -plate_w / 2
edge_r = plate_w / 2
ruler_y0 = -55 mm       # both scales start 5 mm above the bottom edge

solid baseplate {
    body = RoundedRectangle(center=(0, 0), width=plate_w, height=plate_h, corner_radius=6)
    hole capsule {
        c = Circle(center=(0, -15), diameter=40)
    }
    hole lanyard {
        c = Circle(center=(0, -plate_h / 2 + 10 mm), diameter=4)
    }

    drawing arrow {
        a = Polygon([(0, 55), (-8, 40), (-2, 40), (-2, 8), (2, 8), (2, 40), (8, 40)], fill=true)
        left_line = Line((-12, 8), (-12, 55))
        right_line = Line((12, 8), (12, 55))
    }

    drawing ruler {
        for i in range(111) {
            tick = Line((edge_l, ruler_y0 + i * 1 mm),
                        (edge_l + (7 mm if i % 10 == 0 else (5 mm if i % 5 == 0 else 3 mm)),
                         ruler_y0 + i * 1 mm))
        }
        for k in range(12) {
            num = Text(f"{k:.0f}", position=(edge_l + 8 mm, ruler_y0 + k * 10 mm), size=2.5,
                       anchor="start", valign="middle")
        }
    }

    drawing map_scale {
        for i in range(51) {
            tick = Line((edge_r, ruler_y0 + i * 2 mm),
                        (edge_r - (7 mm if i % 10 == 0 else (5 mm if i % 5 == 0 else 3 mm)),
                         ruler_y0 + i * 2 mm))
        }
        for k in range(6) {
            num = Text(f"{k:.0f}", position=(edge_r - 8 mm, ruler_y0 + k * 20 mm), size=2.5,
                       anchor="end", valign="middle")
        }
        # FIX after the first valid program: at the scale's foot "1:50 000" ran into the
        # "0" figure; it now stands over the scale's top (5 km) end
        label = Text("1:50 000", position=(edge_r - 3 mm, ruler_y0 + 105 mm), size=2.5,
                     anchor="end")
    }

    # FIX after the first valid program: W0505, the 0 and 11 cm ticks start 0.08 mm off the
    # material where the R6 corners begin: the ruler as requested, accepted
    AllowOverlap(ruler.tick, self)
    AllowOverlap(map_scale.tick, self)

    # the request's numbers
    assert body.width == 66 mm and body.height == 120 mm, "plate 66 x 120"
    assert capsule.c.diameter == 40 mm and capsule.c.center.y == -15 mm, "capsule hole"
    assert arrow.a.points[0].y - arrow.a.points[3].y == 47 mm, "arrow 47 mm long"
    assert arrow.a.points[0].y == 55 mm, "arrow tip 55 mm above the centre"
    assert arrow.a.points[6].x - arrow.a.points[1].x == 16 mm, "head 16 mm wide"
    assert arrow.right_line.start.x - arrow.left_line.start.x == 24 mm, "lines 24 mm apart"
    assert len(ruler.tick) == 111 and len(ruler.num) == 12, "0-11 cm in mm"
    assert ruler.tick[110].start.y - ruler.tick[0].start.y == 110 mm, "110 mm ruler"
    assert map_scale.tick[10].start.y - map_scale.tick[0].start.y == 20 mm,
        "1 km is 20 mm at 1:50 000"
    assert len(map_scale.num) == 6, "0-5 km"
    assert lanyard.c.center.y - body.bb.bottom == 10 mm and lanyard.c.diameter == 4 mm,
        "lanyard hole"
    # the figures stay clear of the capsule
    assert min([distance(ruler.num[k].position, capsule.c.center) for k in range(12)]) >=
        20 mm + 3 mm, "cm figures clear the capsule"
}
