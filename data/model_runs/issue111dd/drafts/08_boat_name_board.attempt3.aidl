# Request (signs): a name board for the transom of my dinghy, two layers glued: a 6 mm dark backing and
# a 3 mm light face. The backing 520 mm wide, 90 mm tall, curved like a banner: top and bottom edges
# arcs of 1700 mm radius rising 20 mm at the middle, straight ends. The face the same shape 8 mm in
# all round, "KITTIWAKE" cut through it in 40 mm bold serif capitals (stencil bridges) following the
# curve, their middle on the arc 5 mm above the board's middle line, and "WHITBY" (the home port)
# engraved filled, 9 mm sans, along the curve under it. Two M5 countersunk screws 480 mm apart through both layers on the band's middle line.

import "std/fasteners.aidl"

thickness 6 mm

R = 1700 mm
top_c = (0, -1640)       # top arc's centre: the arc's middle at y 60
bot_c = (0, -1730)       # bottom arc's centre: its middle at y -30
half = 260 mm
fhalf = 252 mm           # the face's half width
hole_x = 240 mm
def arc_y(c, r, x) = c[1] + sqrt(r * r - x * x)
mid_y = (arc_y(top_c, R, hole_x) + arc_y(bot_c, R, hole_x)) / 2

assembly name_board {
    solid backing {
        top = Arc(center=top_c, radius=R, start_angle=acos(half / R), end_angle=180 deg - acos(half / R))
        bot = Arc(center=bot_c, radius=R, start_angle=acos(half / R), end_angle=180 deg - acos(half / R))
        right = Line(bot.start, top.start)
        left = Line(top.end, bot.end)
        screw_l = clearance_hole(size=5, cx=-hole_x, cy=mid_y)
        screw_r = clearance_hole(size=5, cx=hole_x, cy=mid_y)
    }
    solid face {
        thickness 3 mm
        top = Arc(center=top_c, radius=R - 8 mm, start_angle=acos(fhalf / (R - 8 mm)),
                  end_angle=180 deg - acos(fhalf / (R - 8 mm)))
        bot = Arc(center=bot_c, radius=R + 8 mm, start_angle=acos(fhalf / (R + 8 mm)),
                  end_angle=180 deg - acos(fhalf / (R + 8 mm)))
        right = Line(bot.start, top.start)
        left = Line(top.end, bot.end)
        hole name {
            path = Circle(center=top_c, radius=R - 40 mm, construction=true)
            word = Text("KITTIWAKE", along=path, size=40, font="serif:Bold", stencil=true,
                        valign="middle")
        }
        drawing port {
            path = Circle(center=bot_c, radius=R + 18 mm, construction=true)
            word = Text("WHITBY", along=path, size=9, font="sans", fill=true, valign="middle")
        }
        screw_l = clearance_hole(size=5, cx=-hole_x, cy=mid_y)
        screw_r = clearance_hole(size=5, cx=hole_x, cy=mid_y)
        Countersink([screw_l, screw_r], diameter=10 mm)
    }

    # on the sheet
    Below(face, backing, gap=10)
    AlignCenterX(face, backing)

    # assembled: the face glued on the backing
    Place(backing, position=(0, 0, 0))
    Place(face, position=(0, 0, 6 mm))

    # the request's numbers
    assert backing.bb.width == 520 mm, "backing 520 wide"
    assert backing.top.radius == 1700 mm and backing.bot.radius == 1700 mm, "1700 mm arcs"
    assert backing.right.length == 90 mm, "90 mm tall at the ends"
    assert backing.top.bb.top - backing.top.start.y == 20 mm, "rises 20 mm at the middle"
    assert backing.bb.width - face.bb.width == 16 mm, "face 8 mm in at the ends"
    assert face.bot.midpoint.y - backing.bot.midpoint.y == 8 mm, "face 8 mm in at the bottom"
    assert backing.top.bb.top - face.top.bb.top == 8 mm, "face 8 mm in at the top"
    assert face.name.word.size == 40 mm, "40 mm capitals"
    assert face.name.word.text == "KITTIWAKE" and face.port.word.text == "WHITBY", "the names"
    # the name's middle 5 mm above the board's middle line (at the middle: (60 + -30) / 2 = 15)
    assert face.name.path.radius + top_c[1] == (60 mm + -30 mm) / 2 + 5 mm, "name 5 above the middle"
    assert face.port.word.bb.top < face.name.word.bb.bottom, "port under the name"
    assert face.screw_r.c.center.x - face.screw_l.c.center.x == 480 mm, "screws 480 apart"
    assert backing.screw_r.c.diameter == 5.5 mm, "M5 clearance"
}
