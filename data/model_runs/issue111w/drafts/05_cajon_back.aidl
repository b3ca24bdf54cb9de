# Music: the back panel of a cajon, 6 mm birch plywood, 300 x 470 mm (sharp
# corners: it sits flush on the box's sides). A 110 mm round sound hole,
# centred left-right, its centre 330 mm above the bottom edge. 16 screw holes
# 4 mm, countersunk 8 mm, 9 mm in from the edges (into the 18 mm frame):
# 4 evenly along the top edge and 4 along the bottom (corners included), and
# 4 more evenly between the corners along each side (6 per side in all).
# "CAJON No. 7" engraved 8 mm high, centred, its baseline 15 mm below the
# sound hole.

thickness 6 mm
param panel_w = 300 mm, min = 250, max = 350
param panel_h = 470 mm, min = 400, max = 520
param inset = 9 mm, min = 6, max = 12

solid back {
    body = Rectangle(center=(0, 0), width=panel_w, height=panel_h)
    hole sound {
        c = Circle(center=(0, -panel_h / 2 + 330), diameter=110)
    }
    hole screws {
        for i in range(4) {
            t = Circle(center=(-panel_w / 2 + inset + i * (panel_w - 2 * inset) / 3, panel_h / 2 - inset), diameter=4)
            b = Circle(center=(-panel_w / 2 + inset + i * (panel_w - 2 * inset) / 3, -panel_h / 2 + inset), diameter=4)
            l = Circle(center=(-panel_w / 2 + inset, -panel_h / 2 + inset + (i + 1) * (panel_h - 2 * inset) / 5), diameter=4)
            r = Circle(center=(panel_w / 2 - inset, -panel_h / 2 + inset + (i + 1) * (panel_h - 2 * inset) / 5), diameter=4)
        }
    }
    Countersink(screws, diameter=8)
    drawing label {
        t = Text("CAJON No. 7", (0, -panel_h / 2 + 330 - 55 - 15), size=8)
    }
    assert body.bb.width == 300 mm and body.bb.height == 470 mm, "panel 300 x 470"
    assert sound.c.diameter == 110 mm, "110 sound hole"
    assert sound.c.center.y - body.bb.bottom == 330 mm, "sound hole 330 up"
    assert len(screws.t) + len(screws.b) + len(screws.l) + len(screws.r) == 16, "16 screws"
    assert screws.t[0].center.x - body.bb.left == 9 mm, "9 in from the side"
    assert body.bb.top - screws.t[0].center.y == 9 mm, "9 in from the top"
    assert sound.c.bottom.y - label.t.position.y == 15 mm, "label 15 below the hole"
}
