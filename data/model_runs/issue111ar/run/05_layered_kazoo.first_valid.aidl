# Request (music): a kazoo glued up from three layers of 3 mm plywood. Every layer has the same
# outline: the hull of a 20 mm circle (the mouthpiece end) and a 34 mm circle whose centres are
# 90 mm apart, and two 3 mm holes for alignment pins at 97 mm from the mouth circle's centre,
# 8 mm either side of the centre line. The middle layer has the air channel cut through: the hull
# of a 10 mm circle at the mouth circle's centre and a 20 mm circle 78 mm along, open at the
# mouth end through a 10 mm wide mouth. The top layer has a 14 mm membrane hole 40 mm from the
# mouth circle's centre and a 14 mm sound hole 78 mm from it, and "KAZOO" engraved between them
# in 4 mm filled bold letters, centred in the gap. The bottom layer is plain. Layers laid flat,
# 5 mm apart.

thickness 3 mm

param pin_d = 3 mm, min = 2 mm, max = 4 mm

def layer(kind="bottom") -> solid {
    mouth_end = Circle(center=(0, 0), diameter=20)
    bell_end = Circle(center=(90, 0), diameter=34)
    outline = Hull(mouth_end, bell_end)
    hole pins {
        a = Circle(center=(97, 8), diameter=pin_d)
        b = Circle(center=(97, -8), diameter=pin_d)
    }
    if kind == "middle" {
        hole channel {
            c0 = Circle(center=(0, 0), diameter=10)
            c1 = Circle(center=(78, 0), diameter=20)
            run = Hull(c0, c1)
            mouth = Rectangle(center=(-8, 0), width=16, height=10, overrun=true)
        }
    }
    if kind == "top" {
        hole membrane {
            c = Circle(center=(40, 0), diameter=14)
        }
        hole sound {
            c = Circle(center=(78, 0), diameter=14)
        }
        drawing label {
            t = Text("KAZOO", (59, 0), size=4, font="sans:Bold", fill=true, valign="middle")
        }
    }
}

assembly kazoo {
    bottom = layer(kind="bottom")
    middle = layer(kind="middle")
    top = layer(kind="top")
    Above(middle, bottom, gap=5)
    AlignLeft(middle, bottom)
    Above(top, middle, gap=5)
    AlignLeft(top, middle)

    assert abs(bottom.bell_end.center.x - bottom.mouth_end.center.x - 90 mm) < 0.01 mm, "ends 90 apart"
    assert abs(bottom.mouth_end.diameter - 20 mm) < 0.01 mm and abs(bottom.bell_end.diameter - 34 mm) < 0.01 mm, "20 and 34 mm ends"
    assert abs(middle.pins.a.center.x - middle.mouth_end.center.x - 97 mm) < 0.01 mm, "pins at 97"
    assert abs(middle.pins.a.center.y - middle.pins.b.center.y - 16 mm) < 0.01 mm, "pins 8 either side"
    assert abs(middle.channel.c1.center.x - middle.channel.c0.center.x - 78 mm) < 0.01 mm, "channel 78 long"
    assert abs(top.membrane.c.center.x - top.mouth_end.center.x - 40 mm) < 0.01 mm, "membrane at 40"
    assert abs(top.sound.c.center.x - top.mouth_end.center.x - 78 mm) < 0.01 mm, "sound hole at 78"
    assert top.label.bb.left > top.membrane.bb.right and top.label.bb.right < top.sound.bb.left, "label between the holes"
    assert abs(top.label.bb.center_x - (top.membrane.bb.right + top.sound.bb.left) / 2) < 0.5 mm, "label centred in the gap"
    assert middle.pins.a.bb.left > middle.channel.bb.right, "pins clear of the channel"
}
