# Request: a mezuzah case for our front door frame, laser-cut from 4 mm walnut ply and glued
# up as a stack of five layers: a back, three spacer frames and a front. Every layer is 36 mm
# wide and 140 mm tall, with a semicircular top (radius 18) and 6 mm bottom corners. The
# spacers have a round-ended slot 16 mm wide and 100 mm long for the rolled scroll (three
# spacers give a 12 mm deep pocket), its bottom 14 mm above the case's bottom. Two holes for
# 3.5 mm wood screws (4 mm) on the centre line, 12 mm below the top and 8 mm above the
# bottom, go through every layer; the front countersinks them 8 mm across. The front has the
# letter shin (ש) cut through, 14 mm tall, its middle 30 mm below the top, an engraved border
# 3 mm inside the edge and an engraved Star of David 18 mm across, its centre 40 mm above the
# bottom.

units mm
thickness 4 mm

T = 4 mm
param W = 36 mm, min = 30 mm, max = 50 mm
param H = 140 mm, min = 120 mm, max = 180 mm
CH_W = 16 mm
CH_L = 100 mm
CH_FROM_BOTTOM = 14 mm
TOP_HOLE = 12 mm
BOT_HOLE = 8 mm
SCREW_D = 4 mm

def layer(channel=false) -> solid {
    body = RoundedRectangle(center=(0, 0), width=W, height=H,
                            corner_radii=[W / 2, W / 2, 6, 6])
    hole top_screw { c = Circle(center=(0, H / 2 - TOP_HOLE), diameter=SCREW_D) }
    hole bottom_screw { c = Circle(center=(0, -H / 2 + BOT_HOLE), diameter=SCREW_D) }
    if channel {
        hole scroll {
            s = Slot(center=(0, -H / 2 + CH_FROM_BOTTOM + CH_L / 2), length=CH_L,
                     width=CH_W, rotation=90)
        }
    }
}

assembly mezuzah {
    back = layer()
    Place(back, position=(0, 0, 0), face="up")

    for i in range(3) {
        spacer = layer(channel=true)
        spacer.body.center.x == (i + 1) * (W + 6 mm)
        spacer.body.center.y == 0
        Place(spacer, position=(0, 0, (i + 1) * T), face="up")
    }

    solid front {
        body = RoundedRectangle(center=(0, 0), width=W, height=H,
                                corner_radii=[W / 2, W / 2, 6, 6])
        hole top_screw { c = Circle(center=(0, H / 2 - TOP_HOLE), diameter=SCREW_D) }
        hole bottom_screw { c = Circle(center=(0, -H / 2 + BOT_HOLE), diameter=SCREW_D) }
        Countersink([top_screw, bottom_screw], diameter=8)
        hole shin {
            t = Text("ש", position=(0, H / 2 - 30), size=14, font="DejaVu Sans:Bold",
                     valign="middle")
        }
        drawing decor {
            border = RoundedRectangle(center=(0, 0), width=W - 6, height=H - 6,
                                      corner_radii=[W / 2 - 3, W / 2 - 3, 3, 3])
            up = RegularPolygon(center=(0, -H / 2 + 40), radius=9, sides=3, rotation=90)
            down = RegularPolygon(center=(0, -H / 2 + 40), radius=9, sides=3, rotation=270)
        }
    }
    front.body.center.x == 4 * (W + 6 mm)
    front.body.center.y == 0
    Place(front, position=(0, 0, 4 * T), face="up")

    assert len(spacer) == 3, "three spacer frames"
    assert front.body.bb.width == 36 mm and front.body.bb.height == 140 mm, "36 x 140"
    assert back.body.bb.width == 36 mm and back.body.bb.height == 140 mm, "36 x 140"
    assert spacer[0].scroll.s.bb.width == 16 mm, "slot 16 wide"
    assert spacer[0].scroll.s.bb.height == 100 mm, "slot 100 long"
    assert spacer[0].scroll.s.bb.bottom - spacer[0].body.bb.bottom == 14 mm,
        "slot 14 above the bottom"
    assert front.body.bb.top - front.top_screw.c.center.y == 12 mm, "screw 12 below the top"
    assert front.bottom_screw.c.center.y - front.body.bb.bottom == 8 mm,
        "screw 8 above the bottom"
    assert front.body.bb.top - front.shin.t.position.y == 30 mm, "shin 30 below the top"
    assert front.decor.up.center.y - front.body.bb.bottom == 40 mm, "star 40 above the bottom"
    assert 3 * T == 12 mm, "a 12 mm deep pocket"
}
