# Running-medal hanger, 6 mm plywood. A rail 300 x 24 mm (corners rounded 4 mm) with
# the word "MARATHON" standing on it in a bold sans font, 45 mm cap height but at most
# 280 mm wide, centred on the rail, the letters sinking 3 mm into the rail so they join it.
# Seven J-hooks hang under the rail, 40 mm apart, centred: each a 6 mm wide round-ended
# band running from 2 mm inside the rail straight down to 24 mm below the rail's bottom,
# round a U of 7 mm centre-line radius, and 6 mm back up (opening 8 mm between the arms).
# Two 4.5 mm screw holes in the rail, 12 mm from its ends, at its mid-height,
# countersunk 9 mm.

units mm
thickness 6 mm

param hooks = 7, min = 3, max = 7
param pitch = 40 mm, min = 35 mm, max = 45 mm

def hook() -> solid {
    drop = Line((0, 2), (0, -24))
    bend = Arc(center=(7, -24), radius=7, start_angle=180, end_angle=360)
    up = Line((14, -24), (14, -18))
    band = Stroke([drop, bend, up], width=6)
}

solid hanger {
    rail = RoundedRectangle(center=(0, 0), width=300, height=24, corner_radius=4)

    solid word {
        t = Text("MARATHON", (0, 9), size=45, font="sans:Bold", max_width=280)
    }
    AlignCenterX(word, rail)
    word.bb.bottom == rail.bb.top - 3

    first = hook()
    row = LinearPattern(first, hooks, (pitch, 0))
    # the hook's top starts 2 mm inside the rail; the row is centred on the rail
    first.drop.start.y == rail.bb.bottom + 2
    (row[0].drop.start.x + row[6].drop.start.x) / 2 == rail.center.x

    hole screw {
        c = Circle(center=(-138, 0), diameter=4.5)
    }
    screws = LinearPattern(screw, 2, (276, 0))
    screw.c.center.x == rail.bb.left + 12
    AlignCenterY(screw, rail)
    Countersink(screw, diameter=9)

    assert rail.bb.width == 300 mm and rail.bb.height == 24 mm, "rail 300 x 24"
    assert word.t.size <= 45 mm and word.bb.width <= 280 mm, "45 mm letters, at most 280 wide"
    assert abs(word.bb.center_x - rail.center.x) < 0.01 mm, "word centred"
    assert rail.bb.top - word.bb.bottom == 3 mm, "letters 3 mm into the rail"
    assert len(row) == 7, "seven hooks"
    assert row[1].drop.start.x - row[0].drop.start.x == 40 mm, "40 mm apart"
    assert rail.bb.bottom - row[0].band.bb.bottom == 24 mm + 7 mm + 3 mm, "hook drops 24 + U radius 7 + half band"
    assert screws[0].c.diameter == 4.5 mm, "4.5 mm screws"
    assert screws[0].c.center.x - rail.bb.left == 12 mm and rail.bb.right - screws[1].c.center.x == 12 mm, "12 mm from the ends"
}
