# Request: a travel box to take a dwarf hamster to the vet, 3 mm ply, finger-jointed,
# 200 long x 140 wide x 110 high outside, with a lid that slides out over the low
# front (so the hamster cannot push it open upwards). Air: a honeycomb of 36 holes
# of 7 mm on the lid (4 rows of 9, 14 mm apart in a row, rows 12 mm apart, every
# other row shifted half a pitch), centred across the lid with the lowest row 8 mm
# below the lid's middle; a row of seven 6 mm holes 15 mm apart across the back,
# 10 mm above its middle. The name "PEANUT" engraved on the lid (filled sans bold,
# 14 mm capitals, baseline 40 mm above the lid's middle) and "LIVE ANIMAL"
# (single-stroke, 8 mm) engraved on the back 25 mm below its middle.
# FIX after the first valid program: `--describe` shows the back's engraved face looks
# into the box (-y, the back stands at y 67..70), so "LIVE ANIMAL" would be inside;
# it moves to the front wall, whose engraved face looks out (-y at y -70..-67).

units mm
thickness 3 mm
import "std/boxes.aidl"

assembly hamster_travel_box {
    box = sliding_lid_box(length=200 mm, width=140 mm, height=110 mm, thickness=3 mm, finger=10 mm)

    hole air { c = Circle(center=(0, 0), diameter=7) }
    lid_air = GridPattern(air, 4, 9, (14, 12), stagger=true)
    At(air.c.center, box.lid.bb.center, dx=-4 * 14 mm - 3.5 mm, dy=-8 mm)
    CutInto(air, box.lid)

    drawing name {
        t = Text("PEANUT", position=(0, 0), size=14, font="sans:Bold", fill=true)
    }
    At(name.t.position, box.lid.bb.center, dy=40 mm)
    CutInto(name, box.lid)

    hole back_air { c = Circle(center=(0, 0), diameter=6) }
    back_row = LinearPattern(back_air, 7, (15, 0))
    At(back_air.c.center, box.back.bb.center, dx=-3 * 15 mm, dy=10 mm)
    CutInto(back_air, box.back)

    drawing warning { t = Text("LIVE ANIMAL", position=(0, 0), size=8) }
    At(warning.t.position, box.front.bb.center, dy=-25 mm)
    CutInto(warning, box.front)

    assert box.bottom.bb.width == 200 mm or box.bottom.bb.height == 200 mm, "200 long"
    assert len(lid_air) == 36, "36 lid holes"
    assert lid_air[1].c.center.x - lid_air[0].c.center.x == 14 mm, "14 mm in a row"
    assert lid_air[9].c.center.y - lid_air[0].c.center.y == 12 mm, "rows 12 apart"
    assert lid_air[0].c.diameter == 7 mm, "7 mm lid holes"
    assert len(back_row) == 7 and back_row[0].c.diameter == 6 mm, "seven 6 mm back holes"
    assert distance(name, lid_air[35]) >= 3 mm, "name clear of the holes"
    assert warning.bb.bottom >= box.front.bb.bottom + 5 mm and warning.bb.top <= box.front.bb.top - 5 mm, "warning on the front"
}
