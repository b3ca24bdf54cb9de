# Request: a new 0-30 V scale and a front bezel for an analogue moving-coil panel meter.
# Scale card, 1 mm white card/acrylic, 60 x 44 mm: the pointer pivots 20 mm below the card's
# centre, where a 6 mm radius notch clears the movement; two 2.2 mm holes for the movement's
# screws at (-22, -16) and (22, -16) from the centre. The scale sweeps 90 degrees (135 to 45 deg)
# about the pivot: an engraved arc at radius 28 mm, 31 ticks (every 1 V) from it out to 31 mm,
# every 5th tick long (to 33 mm) and numbered 0, 5, ... 30 (3 mm digits on a 35 mm radius), and
# a 6 mm "V" below the arc. Bezel, 3 mm black acrylic, 80 x 66 mm with 4 mm corners: a window
# 58 x 42 mm (3 mm corners) 3 mm above its centre, showing the card; a 5 mm hole for the zero
# adjust screw 26 mm below the centre; four M3 countersunk holes (6 mm heads) 6 mm in from
# the corners. Two parts; assembled, the card sits behind the window, 1 mm air gap.

import "std/fasteners.aidl"

units mm
thickness 3 mm

PIVOT_DY = -20 mm

assembly meter_face {
    solid card {
        thickness 1 mm
        body = Rectangle(center=(0, 0), width=60 mm, height=44 mm)
        hole pivot { c = Circle(center=(0, PIVOT_DY), radius=6 mm) }
        hole screws {
            a = Circle(center=(-22 mm, -16 mm), diameter=2.2 mm)
            b = Circle(center=(22 mm, -16 mm), diameter=2.2 mm)
        }
        drawing scale {
            arc = Arc(center=(0, PIVOT_DY), radius=28 mm, start_angle=45 deg, end_angle=135 deg)
            for i in range(31) {
                tick = Line(polar((0, PIVOT_DY), 28 mm, 135 deg - i * 3 deg),
                            polar((0, PIVOT_DY), 33 mm if i % 5 == 0 else 31 mm,
                                  135 deg - i * 3 deg))
            }
            ring = Circle(center=(0, PIVOT_DY), radius=35 mm, construction=true)
            for k in range(7) {
                num = Text(str(5 * k), along=ring, angle=135 deg - k * 15 deg, size=3 mm)
            }
            unit = Text("V", position=(0, -8 mm), size=6 mm)
        }
    }

    solid bezel {
        body = RoundedRectangle(center=(0, 0), width=80 mm, height=66 mm, corner_radius=4 mm)
        hole window {
            w = RoundedRectangle(center=(0, 3 mm), width=58 mm, height=42 mm, corner_radius=3 mm)
        }
        hole zero { c = Circle(center=(0, -26 mm), diameter=5 mm) }
        screw = clearance_hole(size=3)
        corners = CornerPattern(screw, body, inset=6 mm)
        Countersink(corners, diameter=6 mm)
    }

    # flat on the sheet
    RightOf(bezel, card, gap=8 mm)
    AlignCenterY(bezel, card)

    # assembled: the card behind the bezel's window
    Place(card, position=(0, 3 mm, 0))
    Place(bezel, position=(0, 0, 2 mm))

    # the request's numbers
    assert card.body.bb.width == 60 mm and card.body.bb.height == 44 mm, "card 60 x 44"
    assert card.pivot.c.center.y - card.body.bb.center_y == -20 mm, "pivot 20 mm below centre"
    assert len(card.scale.tick) == 31, "31 ticks"
    assert len(card.scale.num) == 7, "numbered 0 to 30 by 5"
    assert card.scale.num[6].text == "30", "ends at 30"
    assert card.screws.b.center.x - card.screws.a.center.x == 44 mm, "screws 44 mm apart"
    assert bezel.body.bb.width == 80 mm and bezel.body.bb.height == 66 mm, "bezel 80 x 66"
    assert bezel.window.w.bb.width == 58 mm and bezel.window.w.bb.height == 42 mm, "window"
    assert bezel.window.w.bb.center_y - bezel.body.bb.center_y == 3 mm, "window 3 mm up"
    assert bezel.body.bb.center_y - bezel.zero.c.center.y == 26 mm, "zero screw 26 mm down"
    assert len(bezel.corners) == 4, "four screws"
    assert card.body.bb.width > bezel.window.w.bb.width, "card fills the window"
    assert card.body.bb.height > bezel.window.w.bb.height, "card fills the window"
}
