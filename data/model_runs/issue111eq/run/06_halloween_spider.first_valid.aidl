# Request: a standing Halloween spider for the mantelpiece, from 4 mm black-stained
# plywood. The body lies flat: a head-and-thorax oval 56 x 44 mm and an abdomen oval
# 72 x 56 mm overlapping it behind (centres 58 mm apart), two 5 mm eyes engraved filled at
# the front and an hourglass mark engraved filled on the abdomen. Four leg pieces stand
# across the body, each a smooth arched band 8 mm wide making a left and a right leg:
# from a foot on the table up over a knee and down to the middle, where a 24 x 10 mm
# block carries a 14 mm tenon up through a 4.2 x 14.2 mm mortise in the thorax; the
# mortises are 10 mm apart. The legs spread (foot to foot centres) 240, 210, 200 and
# 230 mm from front to back, their knees 70, 62, 60 and 66 mm high. Five parts.

units mm
t = 4 mm
thickness t
kerf 0.1 mm

spans = [120 mm, 105 mm, 100 mm, 115 mm]   # half of each leg piece's foot-to-foot spread
knees = [70 mm, 62 mm, 60 mm, 66 mm]
mortise_x = [-15 mm, -5 mm, 5 mm, 15 mm]
shoulder = 39 mm                            # the body's underside above the table

def leg(span=110 mm, knee=65 mm) -> solid {
    path = Spline([(-span, 4), (-0.72 * span, 0.8 * knee), (-0.45 * span, knee), (-22, 33),
                   (0, 31), (22, 33), (0.45 * span, knee), (0.72 * span, 0.8 * knee), (span, 4)])
    band = Stroke(path, width=8)
    block = Rectangle(center=(0, 34), width=24, height=10)
    tenon = Rectangle(bottom_left=(-7, 39), width=14, height=4)
}

assembly spider {
    solid body {
        thorax = Ellipse(center=(0, 0), rx=28, ry=22)
        abdomen = Ellipse(center=(58, 0), rx=36, ry=28)
        for i in range(4) {
            hole mortise {
                m = Rectangle(center=(mortise_x[i], 0), width=4.2, height=14.2)
            }
        }
        drawing marks {
            eye_l = Circle(center=(-22, 6), diameter=5, fill=true)
            eye_r = Circle(center=(-22, -6), diameter=5, fill=true)
            hourglass = Polygon([(48, -9), (68, -9), (58, 0), (68, 9), (48, 9), (58, 0)], fill=true)
        }
        Fixed(thorax)
        assert thorax.rx * 2 == 56 mm and thorax.ry * 2 == 44 mm, "thorax 56 x 44"
        assert abdomen.rx * 2 == 72 mm and abdomen.ry * 2 == 56 mm, "abdomen 72 x 56"
        assert abdomen.center.x - thorax.center.x == 58 mm, "centres 58 mm apart"
        assert len(mortise) == 4, "four mortises"
        assert mortise[1].m.center.x - mortise[0].m.center.x == 10 mm, "mortises 10 mm apart"
        assert distance(marks.eye_l, mortise[0]) >= 1.5 mm, "eyes clear of the front mortise"
    }
    for i in range(4) {
        legs = leg(span=spans[i], knee=knees[i])
        Place(legs, position=(mortise_x[i] - t / 2, 0, 0), face="right", up="up")
    }
    Below(legs[0], body, gap=8)
    AlignCenterX(legs[0], body)
    Below(legs[1], legs[0], gap=6)
    AlignCenterX(legs[1], body)
    Below(legs[2], legs[1], gap=6)
    AlignCenterX(legs[2], body)
    Below(legs[3], legs[2], gap=6)
    AlignCenterX(legs[3], body)
    Place(body, position=(0, 0, shoulder))

    assert len(legs) == 4, "four leg pieces"
    assert legs[0].band.bb.width == 240 mm + 8 mm, "front legs spread 240 mm"
    assert legs[1].band.bb.width == 210 mm + 8 mm and legs[2].band.bb.width == 200 mm + 8 mm and
        legs[3].band.bb.width == 230 mm + 8 mm, "the other legs 210, 200, 230"
    assert legs[0].tenon.width == 14 mm and legs[0].tenon.height == t, "14 mm tenon through the body"
    assert legs[0].tenon.bb.bottom - legs[0].band.bb.bottom == shoulder, "shoulders at the body's underside"
    assert body.mortise[0].m.width - t == 0.2 mm, "0.2 mm play in the mortise"
}
