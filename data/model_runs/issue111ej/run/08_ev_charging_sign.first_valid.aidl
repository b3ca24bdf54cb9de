# Request (signs): a sign for the EV charging bay at our workshop, layered 3 mm acrylic. A green
# backer 300 x 160 mm, R10 corners, on four countersunk M4 screws 12 mm in from each corner
# (8.4 mm heads). Glued on it, cut from white acrylic: a plug pictogram on the left (a body
# 36 wide x 30 tall with R12 lower corners, centred 95 mm left of the middle and 30 up; two
# 6 x 14 mm prongs 18 mm apart standing on its top; a 6 mm cable down from its bottom that
# turns right on a R15 bend), and the letters "EV" (sans bold, 70 mm caps, baseline 5 mm
# below the middle, 6 mm between the letters' boxes, the pair centred 45 mm right of the
# middle). "CHARGING ONLY" engraved filled on the backer (sans bold, 18 mm caps, baseline
# 22 mm above the bottom edge, centred). The white parts cut below the backer, 8 mm apart.

units mm
thickness 3 mm

import "std/fasteners.aidl"

assembly ev_sign {
    solid backer {
        body = RoundedRectangle(center=(0, 0), width=300, height=160, corner_radius=10)
        screw = clearance_hole(size=4)
        screws = CornerPattern(screw, body, inset=12)
        Countersink(screws, diameter=8.4)
        drawing words {
            t = Text("CHARGING ONLY", position=(0, -58), size=18, font="sans:Bold", fill=true)
        }
        AlignCenterX(words.t.position, body)
        words.t.position.y == body.bb.bottom + 22 mm
        Fixed(body)
    }

    solid plug {
        head = RoundedRectangle(center=(-95, 30), width=36, height=30,
                                corner_radii=[0, 0, 12, 12])
        prong_l = Rectangle(center=(-104, 51), width=6, height=14)
        prong_r = Rectangle(center=(-86, 51), width=6, height=14)
        drop = Line((-95, 15), (-95, -10), construction=true)
        bend = Arc(center=(-80, -10), radius=15, start_angle=180 deg, end_angle=270 deg,
                   construction=true)
        cable = Stroke([drop, bend], width=6)
        # prongs stand on the head's top, 18 apart; the cable leaves its bottom middle
        Above(prong_l, head)
        Above(prong_r, head)
        HorizontalDistance(prong_l.center, prong_r.center, 18)
        (prong_l.bb.center_x + prong_r.bb.center_x) / 2 == head.bb.center_x
        Rigid(self)
    }

    solid letter_e {
        # glued parts are Place'd where drawn, so their spots are numbers; the letters'
        # widths (E 40.29, V 63.73) are read off the failed assert of attempt 2
        t = Text("E", position=(30.28, -5), size=70, font="sans:Bold", anchor="end")
    }
    solid letter_v {
        t = Text("V", position=(36.28, -5), size=70, font="sans:Bold", anchor="start")
    }

    Below(plug, backer, gap=8)
    AlignLeft(plug, backer)
    RightOf(letter_e, plug, gap=8)
    AlignTop(letter_e, plug)
    RightOf(letter_v, letter_e, gap=8)
    AlignTop(letter_v, letter_e)

    # stacked: the white parts lie on the backer where they are drawn
    Place(backer, position=(0, 0, 0), face="up")
    Place(plug, position=(0, 0, 3), face="up")
    Place(letter_e, position=(0, 0, 3), face="up")
    Place(letter_v, position=(0, 0, 3), face="up")

    # the request's numbers (Place'd parts are read where they are drawn: on the backer)
    assert abs(backer.body.width - 300 mm) < 0.01 mm and abs(backer.body.height - 160 mm) < 0.01 mm, "backer 300 x 160"
    assert len(backer.screws) == 4, "four screws"
    assert abs(backer.screws[0].c.center.x - backer.body.bb.left - 12 mm) < 0.01 mm, "12 in"
    assert abs(plug.head.center.x - backer.body.center.x + 95 mm) < 0.01 mm and abs(plug.head.center.y - backer.body.center.y - 30 mm) < 0.01 mm, "plug at (-95, 30)"
    assert abs(letter_v.t.bb.left - letter_e.t.bb.right - 6 mm) < 0.01 mm, "6 mm between the letters"
    assert abs((letter_e.t.bb.left + letter_v.t.bb.right) / 2 - 45 mm) < 0.01 mm, "EV centred 45 right"
    assert abs(backer.words.t.position.y - backer.body.bb.bottom - 22 mm) < 0.01 mm, "words 22 up"
    assert letter_e.bb.left >= plug.bb.right + 8 mm, "EV clear of the plug"
    assert letter_v.bb.right <= backer.body.bb.right - 25 mm and letter_v.bb.top <= backer.body.bb.top - 10 mm, "EV on the backer, clear of the screws"
    assert plug.bb.bottom >= backer.words.bb.top + 5 mm and letter_e.bb.bottom >= backer.words.bb.top + 5 mm, "glued parts clear of the engraving"
    assert plug.bb.top <= backer.body.bb.top - 10 mm, "plug on the backer"
}
