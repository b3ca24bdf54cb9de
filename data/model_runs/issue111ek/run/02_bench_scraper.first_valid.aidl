# Request: a bench / dough scraper from 3 mm clear acrylic, 150 wide and 110 tall. The bottom
# edge is the straight working edge (its corners rounded R2 so they do not tear dough); the top
# is a gentle arc rising 15 mm in the middle (95 at the sides, 110 at the middle), its corners
# with the sides rounded R15. A finger-grip slot 90 x 22 (a stadium), centred, its top 20 below
# the top of the arc. A ruler engraved along the working edge: a tick every 5 mm from 5 mm in
# on the left to 5 mm in on the right (29 ticks), 8 mm long at each centimetre, 4 mm between;
# the centimetre numbers 0 to 14 above the long ticks (3 mm tall) and "cm" in the middle above.

units mm
thickness 3 mm
kerf 0.1 mm

W = 150 mm
SIDE_H = 95 mm
H = 110 mm
STEP = 5 mm
TICKS = 29

solid scraper {
    bottom = Line((-W / 2, 0), (W / 2, 0))
    right = Line(bottom.end, (W / 2, SIDE_H))
    top = Arc(start=right.end, through=(0, H), end=(-W / 2, SIDE_H))
    left = Line(top.end, bottom.start)
    Fillet([bottom.start, bottom.end], 2 mm)
    Fillet([right.end, top.end], 15 mm)

    hole grip {
        s = Slot(center=(0, H - 20 - 11), length=90, width=22)
    }

    drawing ruler {
        for i in range(TICKS) {
            tick = Line((-W / 2 + STEP + i * STEP, 0),
                        (-W / 2 + STEP + i * STEP, 8 mm if i % 2 == 0 else 4 mm))
        }
        for k in range(15) {
            num = Text(str(k), position=(-W / 2 + STEP + k * 10 mm, 10), size=3)
        }
        unit = Text("cm", position=(0, 16), size=3)
    }

    assert bottom.length == 150 mm, "150 wide"
    assert top.through.y - bottom.start.y == 110 mm, "110 tall at the middle"
    assert right.end.y - bottom.end.y == 95 mm, "95 at the sides"
    assert grip.s.length == 90 mm and grip.s.width == 22 mm, "grip slot 90 x 22"
    assert top.through.y - grip.s.bb.top == 20 mm, "grip 20 below the top"
    assert len(ruler.tick) == 29, "29 ticks"
    assert ruler.tick[0].start.x - bottom.start.x == 5 mm, "first tick 5 in"
    assert bottom.end.x - ruler.tick[28].start.x == 5 mm, "last tick 5 in"
    assert ruler.tick[2].end.y - ruler.tick[2].start.y == 8 mm, "centimetre ticks 8 long"
    assert ruler.tick[1].end.y - ruler.tick[1].start.y == 4 mm, "half ticks 4 long"
}
