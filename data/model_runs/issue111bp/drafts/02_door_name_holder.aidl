# Request: an office door sign that takes a printed paper insert, so the name can change,
# from 3 mm acrylic in three glued layers, all 220 x 100 mm with 6 mm rounded corners.
# Back: screwed to the door through two 4 mm holes countersunk to 8 mm, 80 mm either side of
# the middle on the centre line. Spacer: a C-shaped frame, 10 mm bars at the left, top and
# bottom, open at the right so a 205 x 80 mm paper slides in from the side. Front: a window
# 180 x 55 mm, its bottom edge 12.5 mm above the plate's bottom and its left edge 15 mm in
# from the left, 3 mm rounded corners; "ROOM 2.14" engraved filled in bold sans, 14 mm high,
# centred over the window in the top border. A 12 mm radius thumb notch in the right edge of
# front and back, centred on the paper, to push the paper out.

thickness 3 mm

W = 220 mm
H = 100 mm

assembly sign {
    solid back {
        body = RoundedRectangle(center=(0, 0), width=W, height=H, corner_radius=6)
        hole screws {
            a = Circle(center=(-80, 0), diameter=4)
            b = Circle(center=(80, 0), diameter=4)
        }
        Countersink(screws, diameter=8 mm)
        hole notch { c = Circle(center=(W / 2, 0), radius=12) }
    }

    solid spacer {
        body = RoundedRectangle(center=(0, 0), width=W, height=H, corner_radius=6)
        hole pocket {
            # runs 5 mm past the right edge: the open side
            r = Rectangle(bottom_left=(-W / 2 + 10, -H / 2 + 10), width=W - 10 + 5, height=H - 20)
        }
    }

    solid front {
        body = RoundedRectangle(center=(0, 0), width=W, height=H, corner_radius=6)
        hole window {
            r = RoundedRectangle(bottom_left=(-W / 2 + 15, -H / 2 + 12.5), width=180, height=55,
                                 corner_radius=3)
        }
        hole notch { c = Circle(center=(W / 2, 0), radius=12) }
        drawing name {
            t = Text("ROOM 2.14", position=(-W / 2 + 15 + 90, (-H / 2 + 12.5 + 55 + H / 2) / 2),
                     size=14, font="sans:Bold", valign="middle", fill=true)
        }
    }

    # 3D: the three layers stacked, back on the door
    Place(back, position=(0, 0, 0))
    Place(spacer, position=(0, 0, 3))
    Place(front, position=(0, 0, 6))

    # on the sheet
    Above(spacer, back, gap=6)
    AlignLeft(spacer, back)
    Above(front, spacer, gap=6)
    AlignLeft(front, back)

    # the request's numbers
    assert back.body.bb.width == 220 mm and back.body.bb.height == 100 mm, "plates 220 x 100"
    assert front.window.r.width == 180 mm and front.window.r.height == 55 mm, "window 180 x 55"
    assert front.window.r.bb.bottom - front.body.bb.bottom == 12.5 mm, "window 12.5 up"
    assert front.window.r.bb.left - front.body.bb.left == 15 mm, "window 15 in"
    assert back.screws.b.center.x - back.screws.a.center.x == 160 mm, "screws 80 either side"
    # the paper (205 x 80) fits the spacer's opening and is held by the window's border
    assert spacer.pocket.r.bb.top - spacer.pocket.r.bb.bottom >= 80 mm, "paper height fits"
    assert spacer.body.bb.right - spacer.pocket.r.bb.left >= 205 mm, "paper length fits"
    assert front.window.r.bb.height < 80 mm, "window smaller than the paper"
    assert front.notch.c.bb.left - front.window.r.bb.right >= 5 mm, "wall between notch and window"
}
