# Request: a lip balm keychain sleeve for a 17 mm lip balm tube, five stacked layers glued:
# - every layer 28 x 90 mm, the top corners rounded 3 mm, the bottom end a full half-round;
#   a 6 mm keyring hole at the centre of that half-round (14 mm up from the bottom);
# - three cores of 6 mm ply, each with a 17.5 mm wide flat-bottomed channel 62 mm deep,
#   open at the top (18 mm deep in all: the tube slides in from the top, its cap stands out);
# - a 3 mm front with an 8 x 44 mm round-ended window (along the length) centred 58 mm up;
# - a 3 mm back with "EMMA" fill-engraved in bold 10 mm letters running up its length,
#   centred 58 mm up, facing out.

units mm
thickness 3 mm

def layer(kind="core") -> solid {
    body = RoundedRectangle(bottom_left=(-14, 0), width=28, height=90, corner_radii=[3, 3, 14, 14])
    hole ring { c = Circle(center=(0, 14), diameter=6) }
    if kind == "core" {
        hole channel {
            ch = Rectangle(bottom_left=(-8.75, 28), width=17.5, height=70, overrun=true)
        }
    }
    if kind == "front" {
        hole window { w = Slot(center=(0, 58), length=44, width=8, rotation=90 deg) }
    }
    if kind == "back" {
        drawing name {
            t = Text("EMMA", position=(0, 58), size=10, font="sans:Bold", rotation=90 deg,
                     valign="middle", fill=true)
        }
    }
    Fixed(body)
    assert body.width == 28 mm and body.height == 90 mm, "28 x 90"
    assert ring.c.center.y - body.bb.bottom == 14 mm, "keyring hole 14 mm up"
}

assembly keychain {
    front = layer(kind="front")
    back = layer(kind="back")
    for i in range(3) {
        solid core {
            thickness 6 mm
            l = layer(kind="core")
        }
    }

    # flat on the sheet, in a row
    RightOf(core[0], back, gap=6)
    AlignBottom(core[0], back)
    for i in range(1, 3) {
        RightOf(core[i], core[i - 1], gap=6)
        AlignBottom(core[i], core[i - 1])
    }
    RightOf(front, core[2], gap=6)
    AlignBottom(front, core[2])

    # assembled: back (engraving down, out), three cores, front on top
    Place(back, position=(0, 0, 3), face="down", up="back")
    for i in range(3) {
        Place(core[i], position=(0, 0, 3 + 6 * i))
    }
    Place(front, position=(0, 0, 21))

    assert len(core) == 3, "three cores"
    assert core[0].l.channel.ch.width == 17.5 mm, "17.5 mm channel"
    assert core[0].l.body.bb.top - core[0].l.channel.ch.bb.bottom == 62 mm, "62 mm deep"
    assert front.window.w.width == 8 mm and front.window.w.length == 44 mm, "8 x 44 window"
    assert front.window.w.center.y - front.body.bb.bottom == 58 mm, "window centred 58 up"
    assert back.name.t.size == 10 mm, "10 mm letters"
    assert distance(back.name, back.ring) >= 3 mm, "name clear of the keyring hole"
    assert back.name.bb.top <= back.body.bb.top - 3 mm, "name on the back"
}
