# Request: an apple-and-honey tray for Rosh Hashanah, two layers of 4 mm ply glued (sealed
# for food). Both layers 260 x 170 mm with 40 mm corners. The top layer has a 72 mm hole
# for the honey jar and an 84 mm hole for the apple, both 5 mm above the middle line, their
# centres 125 mm apart, and a 120 x 14 mm round-ended slot for the honey dipper near the
# front (centre 52 mm below the middle); the base closes them into 4 mm deep pockets.
# Engraved on the top layer: "שנה טובה" (Shana Tova in Hebrew) in bold filled letters 14 mm
# tall across the back, "SHANA TOVA U'METUKAH" 7 mm tall along the front, and a pomegranate
# (a 26 mm circle with a small crown) between the two pockets.

t = 4 mm
thickness t

tray_w = 260 mm
tray_h = 170 mm
jar_d = 72 mm
apple_d = 84 mm
pitch = 125 mm

def outline() = RoundedRectangle(center=(0, 0), width=tray_w, height=tray_h, corner_radius=40)

assembly tray {
    solid base {
        body = outline()
    }

    solid top {
        body = outline()
        hole jar { c = Circle(center=(-70, 5), diameter=jar_d) }
        hole apple { c = Circle(center=(55, 5), diameter=apple_d) }
        hole dipper { s = Slot(center=(0, -52), length=120, width=14) }

        drawing hebrew {
            w = Text("שנה טובה", position=(0, 64), size=14, font="DejaVu Sans:Bold",
                     valign="middle", fill=true)
        }
        drawing english {
            w = Text("SHANA TOVA U'METUKAH", position=(0, -72), size=7, valign="middle")
        }
        drawing pomegranate {
            fruit = Circle(center=(-6, 3), diameter=26)
            crown = Polygon([(-12, 15), (-14, 22), (-9, 18), (-6, 23), (-3, 18), (2, 22), (0, 15)])
        }

        Fixed(body)
        HorizontalDistance(jar.c.center, apple.c.center, pitch)
        VerticalDistance(body.center, jar.c.center, 5 mm)
        VerticalDistance(body.center, apple.c.center, 5 mm)
        # the two pockets together centred across the tray
        (jar.bb.left + apple.bb.right) / 2 == body.center.x
    }

    RightOf(top, base, gap=6)
    AlignTop(top, base)
    Place(base, position=(0, 0, 0), face="up")
    Place(top, position=(0, 0, t), face="up")

    # the request's numbers
    assert top.body.bb.width == 260 mm and top.body.bb.height == 170 mm, "260 x 170 layers"
    assert top.jar.c.diameter == 72 mm and top.apple.c.diameter == 84 mm, "72 and 84 mm pockets"
    assert top.apple.c.center.x - top.jar.c.center.x == 125 mm, "pockets 125 mm apart"
    assert top.dipper.s.length == 120 mm and top.dipper.s.width == 14 mm, "a 120 x 14 slot"
    assert top.body.center.y - top.dipper.s.center.y == 52 mm, "the slot 52 mm below the middle"
    assert distance(top.jar, top.apple) >= 10 mm, "a wall between the pockets"
    assert distance(top.hebrew, top.jar) >= 3 mm and distance(top.hebrew, top.apple) >= 3 mm,
        "the Hebrew clears the pockets"
    assert distance(top.pomegranate, top.jar) >= 3 mm and distance(top.pomegranate, top.apple) >= 3 mm,
        "the pomegranate sits between the pockets"
    assert distance(top.english, top.dipper) >= 3 mm, "the front line clears the dipper slot"
    assert top.english.bb.bottom >= top.body.bb.bottom + 4 mm, "the front line stays on the tray"
}
