# Drill point gauge (workshop): a 100 x 40 mm plate of 3 mm acrylic, corners R3.
# A 118 deg V notch (59 deg each side of the vertical), 10 mm deep, cut into the top edge,
# its axis 25 mm from the left end. A 70 mm ruler engraved along the bottom edge: a tick every
# 1 mm, 3 mm long, 5 mm long every 5 mm, 7 mm long every 10 mm with the numbers 0 to 7 (cm)
# 2 mm above the long ticks (3 mm high); the ruler's zero 15 mm from the left end.
# "118°" engraved 4 mm high beside the notch (centre 62 mm from the left end, 31 mm up).
# A 6 mm hanging hole 8 mm from the right end, centred in height.
units mm
thickness 3 mm

param notch_depth = 10 mm, min = 5 mm, max = 15 mm
param notch_angle = 118 deg, min = 90 deg, max = 140 deg

W = 100 mm
H = 40 mm
notch_x = 25 mm
zero_x = 15 mm
# the notch's flanks run 1 mm past the top edge so the cut leaves no sliver
half = (notch_depth + 1 mm) * tan(notch_angle / 2)

solid gauge {
    body = RoundedRectangle(bottom_left=(0, 0), width=W, height=H, corner_radius=3)

    hole notch {
        v = Polygon([(notch_x, H - notch_depth), (notch_x + half, H + 1), (notch_x - half, H + 1)])
    }

    hole hang {
        c = Circle(center=(W - 8, H / 2), diameter=6)
    }

    drawing ruler {
        for i in range(71) {
            tick = Line((zero_x + i, 0), (zero_x + i, 7 if i % 10 == 0 else (5 if i % 5 == 0 else 3)))
            if i % 10 == 0 {
                num = Text(str(i // 10), (zero_x + i, 9), size=3)
            }
        }
    }

    drawing label {
        t = Text("118°", (62, 31), size=4, valign="middle")
    }

    assert body.bb.width == 100 mm and body.bb.height == 40 mm, "plate 100 x 40"
    assert body.bb.top - notch.bb.bottom == 10 mm, "notch 10 mm deep"
    assert notch.v.points[0].x - body.bb.left == 25 mm, "notch axis 25 mm from the left end"
    assert len(ruler.tick) == 71, "a tick every mm over 70 mm"
    assert ruler.tick[0].start.x - body.bb.left == 15 mm, "zero 15 mm from the left end"
    assert ruler.tick[70].start.x - ruler.tick[0].start.x == 70 mm, "70 mm ruler"
    assert body.bb.right - hang.c.center.x == 8 mm, "hanging hole 8 mm from the right end"
}
