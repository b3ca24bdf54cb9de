# Holidays: a Christmas stocking gift tag / tree ornament, 3 mm birch plywood, 100 mm tall
# overall and 86 mm wide: a smooth stocking outline (a leg 40 mm wide whose top is 75 mm
# above the sole line, the foot pointing right to a rounded toe 58 mm right of the leg's
# middle, heel and sole rounded, the sole's lowest point 12 mm under the sole line) under a
# cuff 56 x 20 mm with R4 corners whose top is 88 mm above the sole line; a 5 mm hanging
# hole in the cuff, its centre 7 mm in from the cuff's left and 8 mm down from its top;
# "2026" in 5 mm strokes engraved in the cuff right of the hole; the name "NOAH" in bold
# sans, 11 mm tall, engraved filled on the leg, its middle 45 mm above the sole line.

thickness 3 mm

param name = "NOAH"

solid stocking {
    sock = Spline([(-20, 75), (20, 75), (21, 45), (22, 24), (40, 17), (58, 6), (52, -8),
                   (20, -12), (-14, -9), (-25, 6), (-21, 40)], closed=true, corners=[0, 1])
    cuff = RoundedRectangle(center=(0, 78), width=56, height=20, corner_radius=4)
    Fixed(sock)
    AlignCenterX(cuff, sock.points[0], )

    hole hang {
        c = Circle(center=(-21, 80), diameter=5)
    }
    hang.c.center.x == cuff.bb.left + 7 mm
    hang.c.center.y == cuff.bb.top - 8 mm

    drawing year {
        t = Text("2026", position=(6, 78), size=5, valign="middle")
    }
    drawing label {
        n = Text(name, position=(0, 45), size=11, font="sans:Bold", valign="middle", fill=true)
    }

    assert cuff.bb.width == 56 mm and cuff.bb.height == 20 mm, "cuff 56 x 20"
    assert cuff.bb.top == 88 mm, "cuff top 88 above the sole line"
    assert sock.points[1].x - sock.points[0].x == 40 mm, "leg 40 wide"
    assert sock.points[5].x == 58 mm, "toe 58 right"
    assert sock.points[7].y == -12 mm, "sole 12 under"
    assert hang.c.diameter == 5 mm, "5 mm hole"
    assert hang.c.center.x - cuff.bb.left == 7 mm and cuff.bb.top - hang.c.center.y == 8 mm, "hole place"
    assert label.n.size == 11 mm and label.n.position.y == 45 mm, "name 11 mm at 45"
}
