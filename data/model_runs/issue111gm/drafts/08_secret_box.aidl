# Request (gifts): a secret box with a gravity-pin lock, 3 mm birch ply, 10 layers glued,
# 120 x 80 mm outside with 4 mm corner radii (30 mm tall).
# Layer 1: the base. Layers 2-6: frames with a 96 x 56 mm opening (3 mm corners), so the
# cavity is 15 mm deep. Layer 7: the same frame with a 4.4 mm pin hole at (54, 26) from the
# box's centre. Layer 8: the channel layer: the outline minus a 104 x 64 mm channel that
# starts 8 mm from the left end and runs out through the right end. The lid: 3 mm, slides
# in the channel with 0.2 mm clearance all round and closes the right end flush; it has the
# pin hole too and "FOR MAYA" (9 mm, sans bold, filled) over "2026" (5 mm) engraved in the
# middle of the window. Layer 9: the retainer, a frame with an 88 x 48 mm window (3 mm
# corners) and the pin hole. Layer 10: the cap, the same frame without the hole.
# A 4 mm dowel 4.5 mm long lives in the pin hole: upright it drops 3 mm into layer 7 and
# locks the lid; turned over it falls into the lid and layer 9 and frees it.

units mm
thickness 3 mm

t = 3 mm
W = 120 mm
Hh = 80 mm
R = 4 mm
pin_d = 4.4 mm
pin_at = (54, 26)
clear = 0.2 mm
ch_left = -W / 2 + 8 mm        # the channel's closed end
ch_w = 64 mm

def outline() = RoundedRectangle(center=(0, 0), width=W, height=Hh, corner_radius=R)

def frame(ow=96 mm, oh=56 mm, pin=false) -> solid {
    body = outline()
    hole opening { o = RoundedRectangle(center=(0, 0), width=ow, height=oh, corner_radius=3) }
    if pin {
        hole pin_hole { c = Circle(center=pin_at, diameter=pin_d) }
    }
}

assembly secret_box {
    solid base { body = outline() }

    for i in range(5) {
        wall = frame()
        wall.bb.center == (130 + i * 130, 0)
        Place(wall, position=(0, 0, t * (i + 1)))
    }

    pin_layer = frame(pin=true)
    pin_layer.bb.center == (0, -90)
    Place(pin_layer, position=(0, 0, 6 * t))

    solid channel {
        body = outline()
        hole slot { s = Rectangle(corner=(ch_left, -ch_w / 2), opposite=(W / 2 + 1, ch_w / 2)) }
    }
    channel.bb.center == (130, -90)
    Place(channel, position=(0, 0, 7 * t))

    solid lid {
        plate = Rectangle(corner=(ch_left + clear, -ch_w / 2 + clear), opposite=(W / 2, ch_w / 2 - clear))
        hole pin_hole { c = Circle(center=pin_at, diameter=pin_d) }
        drawing words {
            name = Text("FOR MAYA", position=(0, 5), size=9, font="sans:Bold", valign="middle", fill=true)
            year = Text("2026", position=(0, -10), size=5, valign="middle")
        }
    }
    lid.bb.center == (260, -90)
    Place(lid, position=(0, 0, 7 * t))

    retainer = frame(ow=88 mm, oh=48 mm, pin=true)
    retainer.bb.center == (390, -90)
    Place(retainer, position=(0, 0, 8 * t))

    cap = frame(ow=88 mm, oh=48 mm)
    cap.bb.center == (520, -90)
    Place(cap, position=(0, 0, 9 * t))

    Place(base, position=(0, 0, 0))

    assert base.body.bb.width == 120 mm and base.body.bb.height == 80 mm, "120 x 80 outside"
    assert len(wall) + 5 == 10, "ten layers"
    assert wall[0].opening.o.width == 96 mm and wall[0].opening.o.height == 56 mm, "96 x 56 cavity"
    assert abs(lid.plate.bb.height - (ch_w - 2 * 0.2 mm)) < 0.001 mm, "lid 0.2 clear of the channel's sides"
    assert abs(lid.plate.bb.left - channel.body.bb.center_x - (ch_left + 0.2 mm)) < 0.001 mm, "0.2 clear of the closed end"
    # FIX after the first valid program: this assert was vacuous (`... < 50 mm`); now it
    # states the request: from 0.2 mm off the channel's closed end to the box's right end
    assert abs(lid.plate.bb.width - (120 mm - 8 mm - 0.2 mm)) < 0.001 mm, "lid reaches the right end"
    assert lid.pin_hole.c.center.x - lid.pin_hole.c.radius - lid.plate.bb.left > 0 mm, "pin hole in the lid"
    # the pin is hidden: under the retainer's band, and inside layer 7's wall band
    assert pin_at[0] - pin_d / 2 > 88 mm / 2 or pin_at[1] - pin_d / 2 > 48 mm / 2, "pin under the retainer"
    assert pin_at[0] - pin_d / 2 > 96 mm / 2 or pin_at[1] - pin_d / 2 > 56 mm / 2, "pin in layer 7's wall"
    assert pin_at[1] + pin_d / 2 < ch_w / 2 - 0.2 mm, "pin hole inside the lid's width"
}
