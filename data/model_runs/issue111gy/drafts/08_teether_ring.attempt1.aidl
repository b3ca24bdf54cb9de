# Request: a new-baby gift: a bunny teether cut from 6 mm maple, with a matching gift tag.
# Teether: a ring 70 mm across with a 45 mm grip hole, two bunny ears on top (ovals 22 x 52 mm
# splayed 15 degrees outward), about 115 mm tall overall, every corner rounded (3 mm: nothing
# sharp for a baby), and the name "ISLA" engraved (filled bold letters, 6 mm) along the bottom
# of the ring, readable. Tag: 60 x 30 mm, 3 mm corners, a 5 mm ribbon hole near its left end,
# "WELCOME ISLA" and "29.11.2026" engraved in single strokes.

units mm
thickness 6 mm
kerf 0.15 mm

assembly baby_gift {
    solid teether {
        ring = Circle(center=(0, 0), diameter=70)
        ear_l = Ellipse(center=(-14, 52), rx=11, ry=26, rotation=15 deg)
        ear_r = Ellipse(center=(14, 52), rx=11, ry=26, rotation=-15 deg)
        hole grip {
            c = Circle(center=(0, 0), diameter=45)
        }
        drawing name {
            mid = Circle(center=(0, 0), radius=(35 + 22.5) / 2, construction=true)
            t = Text("ISLA", along=mid, size=6, font="sans:Bold", fill=true, flip=true,
                     valign="middle")
        }
        Fillet(3 mm)
    }

    solid tag {
        card = RoundedRectangle(center=(0, 0), width=60, height=30, corner_radius=3)
        hole ribbon {
            c = Circle(center=(-24, 0), diameter=5)
        }
        drawing words {
            a = Text("WELCOME ISLA", position=(4, 3), size=5)
            b = Text("29.11.2026", position=(4, -7), size=4)
        }
    }
    RightOf(tag, teether, gap=10)
    AlignBottom(tag, teether)

    assert teether.ring.diameter == 70 mm and teether.grip.c.diameter == 45 mm, "ring and grip"
    assert teether.bb.height >= 105 mm and teether.bb.height <= 125 mm, "about 115 tall"
    assert teether.ear_l.rx * 2 == 22 mm and teether.ear_l.ry * 2 == 52 mm, "ear size"
    assert tag.bb.width == 60 mm and tag.bb.height == 30 mm, "tag size"
    assert tag.ribbon.c.diameter == 5 mm, "5 mm ribbon hole"
    assert distance(tag.words, tag.ribbon) >= 2 mm, "words clear of the ribbon hole"
    assert tag.words.bb.right <= tag.card.bb.right - 2 mm, "words on the tag"
    assert distance(teether.name, teether.grip) >= 1 mm, "name on the ring, off the hole"
}
