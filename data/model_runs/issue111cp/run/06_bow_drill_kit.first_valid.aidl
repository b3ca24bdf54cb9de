# Request (camping): a bow-drill fire-lighting kit laser-cut from 10 mm basswood (the ember pan
# from 3 mm ply), four loose parts:
# - Fireboard 220 x 45 mm: five starter divots 16 mm across (engraved filled, the laser's
#   engraving makes the shallow pit) 40 mm apart along it, their centres 12 mm in from the
#   front edge; under each a 45-degree V notch cut from the front edge to the divot's centre.
# - Bearing block (handhold): a 90 x 60 mm oval with a 14 mm engraved divot at its centre
#   and "BEARING" engraved under it.
# - Bow: a curved bar 24 mm wide, about 500 mm long tip to tip, bent on a 580 mm radius,
#   with a 5 mm cord hole at the centre of each rounded end and 5 engraved grip lines at
#   the middle.
# - Ember pan (3 mm ply): 110 x 60 mm, 5 mm corners, a 30 x 20 mm tab at one end with an
#   8 mm thumb hole; "EMBER" engraved.

units mm
thickness 10 mm

divots = 5
pitch = 40 mm
divot_in = 12 mm
R = 580 mm
half = 24 deg     # half the bow's arc

assembly bow_drill {
    solid fireboard {
        body = Rectangle(center=(0, 0), width=220, height=45)
        hole notches {
            for i in range(divots) {
                v = Triangle((-80 + pitch * i - 13 * tan(22.5 deg), -23.5),
                             (-80 + pitch * i + 13 * tan(22.5 deg), -23.5),
                             (-80 + pitch * i, -22.5 + divot_in))
            }
        }
        drawing pits {
            for i in range(divots) {
                d = Circle(center=(-80 + pitch * i, -22.5 + divot_in), diameter=16, fill=true)
            }
        }
        # each divot is opened by its notch, as on any fireboard: its engraving crosses it
        AllowOverlap(pits.d, self)
    }

    solid handhold {
        oval = Ellipse(center=(0, 0), rx=45, ry=30)
        drawing pit {
            d = Circle(center=(0, 0), diameter=14, fill=true)
            word = Text("BEARING", position=(0, -17), size=5, valign="middle")
        }
    }

    solid bow {
        bar = ArcSlot(center=(0, -R), radius=R, start_angle=90 deg - half,
                      end_angle=90 deg + half, width=24)
        hole cord {
            a = Circle(center=(R * cos(90 deg - half), -R + R * sin(90 deg - half)), diameter=5)
            b = Circle(center=(R * cos(90 deg + half), -R + R * sin(90 deg + half)), diameter=5)
        }
        drawing grip {
            for k in range(5) {
                g = Line(((R - 8) * cos((86 + 2 * k) * 1 deg), -R + (R - 8) * sin((86 + 2 * k) * 1 deg)),
                         ((R + 8) * cos((86 + 2 * k) * 1 deg), -R + (R + 8) * sin((86 + 2 * k) * 1 deg)))
            }
        }
    }

    solid pan {
        thickness 3 mm
        tray = RoundedRectangle(center=(0, 0), width=110, height=60, corner_radius=5)
        tab = Rectangle(center=(-65, 0), width=30, height=20)
        hole thumb { c = Circle(center=(-70, 0), diameter=8) }
        drawing label { word = Text("EMBER", position=(5, 0), size=8, valign="middle") }
    }

    # on the sheet
    Below(fireboard, bow, gap=8)
    AlignLeft(fireboard, bow)
    RightOf(handhold, fireboard, gap=8)
    AlignTop(handhold, fireboard)
    RightOf(pan, handhold, gap=8)
    AlignTop(pan, fireboard)

    assert fireboard.body.width == 220 mm and fireboard.body.height == 45 mm, "fireboard 220 x 45"
    assert len(fireboard.pits.d) == 5 and len(fireboard.notches.v) == 5, "five divots, five notches"
    assert fireboard.pits.d[1].center.x - fireboard.pits.d[0].center.x == 40 mm, "40 mm apart"
    assert fireboard.pits.d[0].center.y - fireboard.body.bb.bottom == 12 mm, "12 mm in"
    assert fireboard.notches.v[0].c == fireboard.pits.d[0].center, "notch to the divot's centre"
    assert handhold.oval.bb.width == 90 mm and handhold.oval.bb.height == 60 mm, "block 90 x 60"
    assert abs(bow.bb.width - 500 mm) < 10 mm, "bow about 500 mm"
    assert bow.bar.width == 24 mm, "bow 24 mm wide"
    assert pan.tray.width == 110 mm and pan.tab.width == 30 mm and pan.tab.height == 20 mm, "pan and tab"
}
