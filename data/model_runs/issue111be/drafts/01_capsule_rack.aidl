# Request (kitchen): a wall-mounted coffee-capsule dispenser for Nespresso "original" capsules
# (rim 37 mm across, body 30 mm across), cut from 3 mm birch ply as three layers screwed
# together: a 176 x 340 mm back, a spacer and a front, all with 6 mm rounded corners and four
# M4 screw holes 11 mm in from the sides and 20 mm in from top and bottom (countersunk 9 mm on
# the front). Three columns 48 mm apart hold 8 capsules each: the spacer has a 39 mm wide channel
# per column, open at the top, ending round 50 mm above the bottom edge; the front has a 31 mm
# wide channel per column (the body slides, the rim is held) ending in a 39 mm release hole 50 mm
# above the bottom, so the lowest capsule tips out forward. "COFFEE" engraved filled, 10 mm
# high, centred 12 mm above the bottom of the front.

units mm
thickness 3 mm

param cols = 3, min = 1, max = 4
param per_col = 8, min = 4, max = 10

# FIX after the first valid program: W0115 said per_col was read by nothing; the plate's height
# now follows it (30.5 mm below the lowest rim, 13.5 mm above the top one: 340 mm for 8)
W = 176 mm
pitch = 48 mm
rim = 37 mm
H = 30.5 mm + per_col * rim + 13.5 mm
body_d = 30 mm
spacer_w = 39 mm
front_w = 31 mm
release_y = -H / 2 + 50 mm

def capsule_plate(kind=0) -> solid {
    body = RoundedRectangle(center=(0, 0), width=W, height=H, corner_radius=6)
    hole screw { c = Circle(center=(-W / 2 + 11, -H / 2 + 20), diameter=4.5) }
    screws = CornerPattern(screw, body, inset=(11, 20))
    Fixed(body)
    if kind == 0 {
        Countersink(screws, diameter=9)
        hole chan {
            for i in range(cols) {
                bar = Rectangle(corner=((i - (cols - 1) / 2) * pitch - front_w / 2, release_y),
                                opposite=((i - (cols - 1) / 2) * pitch + front_w / 2, H / 2 + 1))
                out = Circle(center=((i - (cols - 1) / 2) * pitch, release_y), diameter=spacer_w)
            }
        }
        drawing label {
            t = Text("COFFEE", position=(0, -H / 2 + 12), size=10, font="sans:Bold",
                     valign="middle", fill=true)
        }
    }
    if kind == 1 {
        hole chan {
            for i in range(cols) {
                s = Slot(start=((i - (cols - 1) / 2) * pitch, release_y),
                         end=((i - (cols - 1) / 2) * pitch, H / 2 + spacer_w / 2 + 1),
                         width=spacer_w)
            }
        }
    }
}

assembly capsule_rack {
    back = capsule_plate(kind=2)
    spacer = capsule_plate(kind=1)
    front = capsule_plate(kind=0)

    # flat on the sheet side by side; stacked in 3D: back on the wall, front outermost
    RightOf(spacer, back, gap=10)
    RightOf(front, spacer, gap=10)
    AlignBottom(spacer, back)
    AlignBottom(front, back)
    Place(back, position=(0, 0, 0))
    Place(spacer, position=(0, 0, 3))
    Place(front, position=(0, 0, 6))

    # the request's numbers
    assert len(front.screws) == 4, "four screws"
    assert front.body.bb.width == 176 mm and front.body.bb.height == 340 mm, "plate 176 x 340"
    assert len(front.chan.bar) == 3 and len(spacer.chan.s) == 3, "three columns"
    assert front.chan.out[1].center.x - front.chan.out[0].center.x == 48 mm, "columns 48 mm apart"
    assert front.chan.bar[0].bb.width == 31 mm, "front channel 31 mm: the 30 mm body slides"
    assert front_w > body_d and front_w < rim, "the front holds the rim, passes the body"
    assert spacer.chan.s[0].width == 39 mm and spacer_w > rim, "spacer channel passes the rim"
    assert front.chan.out[0].diameter > rim, "release hole lets the rim out"
    assert front.chan.out[0].center.y - front.body.bb.bottom == 50 mm, "release 50 mm up"
    assert spacer.chan.s[0].start.y - spacer.body.bb.bottom == 50 mm, "channel ends 50 mm up"
    # 8 capsules stacked rim on rim fit between the channel's end and the top edge
    assert spacer.body.bb.top - (spacer.chan.s[0].start.y - spacer_w / 2) >= per_col * rim, "holds per_col"
    assert per_col != 8 or H == 340 mm, "340 mm high for 8 capsules"
    assert front.screws[0].c.center.x - front.body.bb.left == 11 mm, "screws 11 mm in"
    assert front.screws[0].c.center.y - front.body.bb.bottom == 20 mm, "screws 20 mm up"
    # the screws miss the outer channels
    assert (front.screws[1].c.center.x - 4.5 / 2) - (spacer.chan.s[2].start.x + spacer_w / 2) >= 3 mm,
        "screw clear of the channel"
    assert front.label.t.position.y - front.body.bb.bottom == 12 mm, "label 12 mm up"
}
