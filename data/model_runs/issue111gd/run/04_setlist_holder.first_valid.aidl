# Request (music): a setlist holder for a mic stand, 3 mm birch ply, for an A6 card (105 x
# 148 mm, portrait) slid in from the top. Three glued layers, each 128 x 172 mm with R6
# corners: a back plate; a U-shaped spacer (10 mm side arms, 20 mm bottom) that leaves a
# 108 mm wide pocket, open at the top; a front frame (14 mm side arms, 26 mm bottom) whose
# arms overlap the card's edges, "THE LOCALS" engraved filled (bold sans, 7 mm) on its
# bottom bar. It clamps to the stand's tube (19-25 mm) between the back plate and two rear
# jaws (60 x 30 mm, R5), centred 45 mm and 135 mm up the back plate, each with two M4 bolts
# 40 mm apart and wing nuts; the bolt heads countersunk (9 mm, 90 deg) flush in the back
# plate's front face, under the card.

import "std/fasteners.aidl"

thickness 3 mm

t = 3 mm
w = 128 mm
h = 172 mm
r = 6 mm
jaw_y = [45 mm, 135 mm]
bolt_dx = 20 mm
card_w = 105 mm
card_h = 148 mm
tube_max = 25 mm

def jaw() -> solid {
    plate = RoundedRectangle(center=(0, 0), width=60, height=30, corner_radius=5)
    hole bolts {
        a = Circle(center=(-bolt_dx, 0), diameter=4.5)
        b = Circle(center=(bolt_dx, 0), diameter=4.5)
    }
}

assembly holder {
    solid back {
        plate = RoundedRectangle(corner=(-w / 2, 0), opposite=(w / 2, h), corner_radius=r)
        hole bolts {
            for i in range(2) {
                a = Circle(center=(-bolt_dx, jaw_y[i]), diameter=4.5)
                b = Circle(center=(bolt_dx, jaw_y[i]), diameter=4.5)
            }
        }
        Countersink(bolts, diameter=9 mm)
    }

    solid spacer {
        plate = RoundedRectangle(corner=(-w / 2, 0), opposite=(w / 2, h), corner_radius=r)
        hole pocket {
            p = Rectangle(corner=(-w / 2 + 10 mm, 20), opposite=(w / 2 - 10 mm, h + 5 mm))
        }
    }

    solid frame {
        plate = RoundedRectangle(corner=(-w / 2, 0), opposite=(w / 2, h), corner_radius=r)
        hole window {
            p = Rectangle(corner=(-w / 2 + 14 mm, 26), opposite=(w / 2 - 14 mm, h + 5 mm))
        }
        drawing band {
            name = Text("THE LOCALS", position=(0, 13), size=7, font="sans:Bold",
                        valign="middle", fill=true)
        }
    }

    upper = jaw()
    lower = jaw()

    # flat on the sheet
    RightOf(spacer, back, gap=8)
    AlignBottom(spacer, back)
    RightOf(frame, spacer, gap=8)
    AlignBottom(frame, spacer)
    Below(lower, back, gap=8)
    AlignLeft(lower, back)
    RightOf(upper, lower, gap=8)
    AlignTop(upper, lower)

    # assembled: layers front to back, the tube (not cut) between the back plate and the jaws
    Place(frame, position=(0, -t, 0), face="front", up="up")
    Place(spacer, position=(0, 0, 0), face="front", up="up")
    Place(back, position=(0, t, 0), face="front", up="up")
    Place(lower, position=(0, t + 22 mm + t, jaw_y[0]), face="front", up="up")
    Place(upper, position=(0, t + 22 mm + t, jaw_y[1]), face="front", up="up")

    assert back.plate.bb.width == 128 mm and back.plate.bb.height == 172 mm, "128 x 172"
    assert spacer.pocket.p.bb.width == 108 mm, "108 pocket"
    assert spacer.pocket.p.bb.width >= card_w + 2 mm, "the card slides in"
    assert back.plate.bb.top - spacer.pocket.p.bb.bottom >= card_h, "the card fits its height"
    assert frame.window.p.bb.width < card_w, "the arms overlap the card"
    assert frame.window.p.bb.bottom - frame.plate.bb.bottom == 26 mm, "26 mm bottom bar"
    assert spacer.pocket.p.bb.bottom - spacer.plate.bb.bottom == 20 mm, "20 mm spacer bottom"
    assert back.bolts.a[0].center.y - back.plate.bb.bottom == 45 mm, "lower jaw at 45"
    assert back.bolts.a[1].center.y - back.plate.bb.bottom == 135 mm, "upper jaw at 135"
    assert back.bolts.b[0].center.x - back.bolts.a[0].center.x == 40 mm, "bolts 40 apart"
    assert 2 * bolt_dx - 4.5 mm > tube_max, "a 25 mm tube passes between the bolts"
    assert distance(frame.band, frame.window) >= 2 mm, "name clear of the window"
}
