# Request: a giant number "7" pinata for Mia's 7th birthday, cut from 2 mm greyboard.
# Two faces: the digit "7" in a bold sans font, 450 mm tall (cap height), each with two 8 mm
# holes for the hanging cord 60 mm either side of the middle, 15 mm below the top edge;
# "MIA" engraved filled 40 mm tall on the top bar, centred 50 mm below the top.
# The back face also has a 50 x 50 mm filling door: three sides cut, the top edge scored as
# its hinge, its top-left corner 30 mm in from the digit's left edge and 15 mm down.
# The side wall: three strips 100 mm wide (the pinata's depth) x 560 mm, joined end to end by
# a flat dovetail (2 tails, 12 mm deep, 15 deg), each with 13 glue tabs (30 mm at the base,
# 18 at the tip, 15 deep) every 40 mm along both long edges and a score line along each edge.
# Every part must fit a 600 x 400 mm bed.

import "std/joints.aidl"

units mm
thickness 2 mm

strip_w = 100 mm
strip_len = 560 mm
dt_depth = 12 mm

def face(door=false) -> solid {
    seven = Text("7", position=(0, 0), size=450, font="sans:Bold", valign="middle")
    hole hang {
        a = Circle(center=(-60, 0), diameter=8)
        b = Circle(center=(60, 0), diameter=8)
    }
    AlignCenterX(hang, seven)
    hang.a.center.y == seven.bb.top - 15 mm
    drawing name {
        n = Text("MIA", position=(0, 0), size=40, font="sans:Bold", valign="middle", fill=true)
    }
    AlignCenterX(name, seven)
    name.n.position.y == seven.bb.top - 50 mm
    if door {
        cut flap {
            u = Polyline([(0, 0), (0, -50), (50, -50), (50, 0)])
        }
        drawing hinge {
            h = Line((0, 0), (50, 0))
        }
        flap.u.start.x == seven.bb.left + 30 mm
        flap.u.start.y == seven.bb.top - 15 mm
        Coincident(hinge.h.start, flap.u.start)
    }
}

def strip() -> solid {
    body = Rectangle(bottom_left=(-strip_len / 2, -strip_w / 2), width=strip_len + dt_depth,
                     height=strip_w)
    for i in range(13) {
        top_tab = Trapezoid(center=(-240 + i * 40, strip_w / 2 + 7.5), bottom_width=30,
                            top_width=18, height=15)
        bottom_tab = Trapezoid(center=(-240 + i * 40, -strip_w / 2 - 7.5), bottom_width=30,
                               top_width=18, height=15, rotation=180 deg)
    }
    tails = dovetail(part="tail", length=strip_w, depth=dt_depth, tails=2, angle=15 deg,
                     rotation=-90 deg, cx=strip_len / 2, cy=0 mm)
    sockets = dovetail(part="socket", length=strip_w, depth=dt_depth, tails=2, angle=15 deg,
                       rotation=-90 deg, cx=-strip_len / 2, cy=0 mm)
    drawing score {
        upper = Line((-strip_len / 2, strip_w / 2), (strip_len / 2, strip_w / 2))
        lower = Line((-strip_len / 2, -strip_w / 2), (strip_len / 2, -strip_w / 2))
    }
}

assembly number_pinata {
    front = face()
    back = face(door=true)
    side_a = strip()
    side_b = strip()
    side_c = strip()

    RightOf(back, front, gap=10)
    AlignTop(back, front)
    Below(side_a, front, gap=10)
    AlignLeft(side_a, front)
    Below(side_b, side_a, gap=10)
    AlignLeft(side_b, side_a)
    Below(side_c, side_b, gap=10)
    AlignLeft(side_c, side_b)

    # the request's numbers
    assert front.seven.size == 450 mm, "7 is 450 tall"
    assert back.hang.b.center.x - back.hang.a.center.x == 120 mm, "cord holes 60 either side"
    assert len(side_a.top_tab) == 13 and len(side_a.bottom_tab) == 13, "13 tabs each edge"
    assert side_a.top_tab[1].center.x - side_a.top_tab[0].center.x == 40 mm, "tabs every 40"
    assert side_a.body.bb.height == 100 mm, "strips 100 wide"
    assert front.bb.width <= 400 mm and front.bb.height <= 600 mm, "a face fits the bed"
    assert side_a.bb.width <= 600 mm and side_a.bb.height <= 400 mm, "a strip fits the bed"
}
