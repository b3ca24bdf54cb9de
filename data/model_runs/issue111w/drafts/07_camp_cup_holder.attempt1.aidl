# Camping: a clip-on cup holder for a camp chair, 6 mm acrylic, a plate
# 160 x 100 mm with 10 mm rounded corners. An 80 mm hole for the mug, its
# centre 50 mm from the left edge, centred top-bottom. At the right end a
# U-notch slides onto the chair's 22 mm upright tube: 22.4 mm wide, running
# in from the right edge, its round end's centre 35 mm in from that edge; the
# two corners where the notch meets the edge rounded 2 mm. "CAMP" engraved
# 6 mm high, centred between the mug hole and the notch's round end.

thickness 6 mm
param tube = 22 mm, min = 16, max = 32
param fit = 0.4 mm, min = 0, max = 1

solid holder {
    body = RoundedRectangle(center=(0, 0), width=160, height=100, corner_radius=10)
    hole mug {
        c = Circle(center=(-30, 0), diameter=80)
    }
    hole notch {
        end = Circle(center=(80 - 35, 0), diameter=tube + fit)
        mouth = Rectangle(corner=(45, -(tube + fit) / 2), opposite=(81, (tube + fit) / 2))
    }
    Fillet([(80, (tube + fit) / 2), (80, -(tube + fit) / 2)], 2)
    drawing label {
        t = Text("CAMP", (0, 0), size=6, valign="middle")
    }
    label.t.position.x == (mug.c.right.x + notch.end.left.x) / 2
    assert body.bb.width == 160 mm and body.bb.height == 100 mm, "plate 160 x 100"
    assert mug.c.diameter == 80 mm, "80 mm mug hole"
    assert mug.c.center.x - body.bb.left == 50 mm, "mug 50 from the left"
    assert notch.end.diameter == 22.4 mm, "notch 22.4 wide"
    assert body.bb.right - notch.end.center.x == 35 mm, "notch end 35 in"
}
