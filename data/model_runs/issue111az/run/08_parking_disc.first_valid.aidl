# Request: a parking disc (the "arrival time" sign for the dashboard) from two pieces of
# 3 mm ply held by a 4 mm Chicago screw.
# - Face: 110 x 150 mm, R8 corners, the screw hole 10 mm below its centre, a 22 x 9 mm
#   window centred 46 mm above the screw, a small engraved arrow (6 wide, 4 tall) under the
#   window pointing at it, "ARRIVAL TIME" engraved 6 mm tall above the window, and a big
#   filled "P" (40 mm, bold) engraved in the lower half.
# - Dial behind it: 116 mm across (3 mm proud of the face each side to turn it with a
#   thumb), the same 4 mm hole in its centre, 48 grip notches (R2) round its rim, the
#   hours 0 to 23 engraved 4 mm tall round a 44 mm radius (0 at the top, clockwise), a
#   tick from 44 to 48 mm radius at every half hour between them.

thickness 3 mm

face_w = 110 mm
face_h = 150 mm
pivot_y = -10 mm
label_r = 44 mm
dial_d = 116 mm

assembly parking_disc {
    solid face {
        card = RoundedRectangle(center=(0, 0), width=face_w, height=face_h, corner_radius=8 mm)
        hole pivot {
            c = Circle(center=(0, pivot_y), diameter=4 mm)
        }
        hole window {
            r = Rectangle(center=(0, pivot_y + 46 mm), width=22 mm, height=9 mm)
        }
        drawing marks {
            pointer = Triangle(center=(0, pivot_y + 46 mm - 9 mm), base=6 mm, height=4 mm)
            title = Text("ARRIVAL TIME", position=(0, pivot_y + 46 mm + 12 mm), size=6 mm)
        }
        drawing sign {
            p = Text("P", position=(0, -40 mm), size=40 mm, font="sans:Bold", valign="middle",
                     fill=true)
        }
    }

    solid dial {
        disc = Circle(center=(0, 0), diameter=dial_d)
        hole pivot {
            c = Circle(center=(0, 0), diameter=4 mm)
        }
        hole notch {
            n = Circle(center=(dial_d / 2, 0), radius=2 mm)
        }
        grip = CircularPattern(notch, 48, disc.center)
        drawing hours {
            ring = Circle(center=(0, 0), radius=label_r, construction=true)
            for h in range(24) {
                t = Text(str(h), along=ring, angle=90 deg - h * 15 deg, size=4 mm)
                tick = Line(start=polar(ring.center, label_r, 90 deg - h * 15 deg - 7.5 deg),
                            length=4 mm, angle=90 deg - h * 15 deg - 7.5 deg)
            }
        }
    }

    # flat on the sheet
    RightOf(dial, face, gap=5 mm)
    AlignBottom(dial, face)

    # in 3D: the dial behind the face on the screw
    Place(dial, position=(0, pivot_y, 0))
    Place(face, position=(0, 0, 3 mm))

    # the request's numbers
    assert face.card.width == 110 mm and face.card.height == 150 mm, "face 110 x 150"
    assert face.card.center.y - face.pivot.c.center.y == 10 mm, "screw 10 below the centre"
    assert face.window.r.center.y - face.pivot.c.center.y == 46 mm, "window 46 above the screw"
    assert face.window.r.width == 22 mm and face.window.r.height == 9 mm, "22 x 9 window"
    assert dial.disc.diameter - face.card.width == 6 mm, "dial 3 mm proud each side"
    assert len(dial.grip) == 48, "48 notches"
    assert len(dial.hours.t) == 24 and len(dial.hours.tick) == 24, "24 hours, 24 half-hour ticks"
    # the hour at the top lies wholly in the window (its letters from 44 to 48 mm out)
    assert face.window.r.bb.bottom - face.pivot.c.center.y < label_r, "window reaches below the numbers"
    assert face.window.r.bb.top - face.pivot.c.center.y > label_r + 4 mm, "window reaches above the numbers"
}
