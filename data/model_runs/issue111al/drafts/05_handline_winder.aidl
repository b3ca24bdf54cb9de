# Request (camping): a fishing handline winder that doubles as a fish ruler, cut from 5 mm
# acrylic. A 200 x 70 mm plate with R5 corners; a V notch in each end for the line to wrap
# into (32 mm wide at the end, 22 mm deep, a 4 mm round bottom), filleted R3 where it meets
# the end; a 70 x 22 mm finger slot across the middle, 6 mm above the centre line; a 4 mm hole
# to tie the line on (60 mm left of centre, 22 mm up) and a 10 x 2.5 mm slot to park the hook
# (60 mm right, 24 mm up). Along the bottom edge an engraved 20 cm ruler measured from the
# left end: ticks every 5 mm starting 1 mm in from the edge (3 mm long, whole cm 5 mm, every
# 5 cm 8 mm), numbered 5, 10, 15 above their ticks; "FISH RULER CM" engraved above the slot.

thickness 5 mm

L = 200 mm
H = 70 mm

solid winder {
    body = RoundedRectangle(center=(0, 0), width=L, height=H, corner_radius=5 mm)
    hole notch_l {
        v = Hull(Circle(center=(-L / 2 + 22 mm - 4 mm, 0), radius=4 mm),
                 Point(-L / 2 - 2 mm, 16 mm * (1 + 2 / 22)), Point(-L / 2 - 2 mm, -16 mm * (1 + 2 / 22)),
                 overrun=true)
    }
    hole notch_r {
        v = Hull(Circle(center=(L / 2 - 22 mm + 4 mm, 0), radius=4 mm),
                 Point(L / 2 + 2 mm, 16 mm * (1 + 2 / 22)), Point(L / 2 + 2 mm, -16 mm * (1 + 2 / 22)),
                 overrun=true)
    }
    # every other corner of the outline is already round (R5 corners, the notches' round
    # bottoms, slots, holes): a plain Fillet rounds just the four notch mouths
    Fillet(3 mm)
    hole grip { s = Slot(center=(0, 6 mm), length=70 mm, width=22 mm) }
    hole tie { c = Circle(center=(-60 mm, 22 mm), diameter=4 mm) }
    hole hook { s = Slot(center=(60 mm, 24 mm), length=10 mm, width=2.5 mm) }

    drawing ruler {
        for i in range(1, 40) {
            tick = Line((-L / 2 + i * 5 mm, -H / 2 + 1 mm),
                        (-L / 2 + i * 5 mm,
                         -H / 2 + 1 mm + (8 mm if i % 10 == 0 else (5 mm if i % 2 == 0 else 3 mm))))
        }
        for cm in [5, 10, 15] {
            num = Text(f"{cm}", position=(-L / 2 + cm * 10 mm, -H / 2 + 11 mm), size=4)
        }
        title = Text("FISH RULER CM", position=(0, 24 mm), size=4)
    }

    assert body.width == 200 mm and body.height == 70 mm, "200 x 70 plate"
    assert len(ruler.tick) == 39, "ticks every 5 mm inside 20 cm"
    assert ruler.tick[9].end.y - ruler.tick[9].start.y == 8 mm, "5 cm tick 8 mm long"
    assert ruler.tick[1].end.y - ruler.tick[1].start.y == 5 mm, "1 cm tick 5 mm long"
    assert ruler.tick[9].start.x - body.bb.left == 50 mm, "5 cm mark 50 mm from the left end"
    assert notch_l.v.bb.right - body.bb.left == 22 mm, "notch 22 mm deep"
    assert grip.s.length == 70 mm and grip.s.width == 22 mm, "70 x 22 finger slot"
    assert ruler.num[0].bb.top < grip.s.center.y - 11 mm, "numbers below the finger slot"
    assert ruler.title.bb.bottom > grip.s.center.y + 11 mm, "title above the finger slot"
}
