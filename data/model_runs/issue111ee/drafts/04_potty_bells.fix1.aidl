# Request (pets): potty-training bells for the back door: the dog nudges the bells when it wants
# to go out. 4 mm ply, one piece.
# - A strip 70 mm wide and 300 mm long with fully rounded ends (R35), hung on the door's lever
#   handle: an opening 24 mm wide x 60 mm long (rounded ends), upright, its top 15 mm below the
#   strip's top, for the lever to pass through.
# - Five bells tied on with cord, each through a pair of 4 mm holes 10 mm apart; the pairs 25 mm
#   apart down the middle, the lowest pair 15 mm above the bottom edge.
# - A paw print engraved filled (a pad 22 x 18 mm and four toes around it) and "RING" (9 mm) over
#   "TO GO OUT" (6 mm) under it, bold sans, engraved filled, between the opening and the bells.

thickness 4 mm

param bells = 5, min = 3, max = 5
width = 70 mm
length = 300 mm
# FIX after the first valid program: the toes ran into each other (one lumpy blob); spread them
# further out and make them smaller, with asserts on the gaps
def toe_angle(i) = 40 deg + i * 33 deg

solid potty_bells {
    strip = Slot(start=(0, 0), end=(0, -(length - width)), width=width)
    hole handle {
        s = Slot(center=(0, -10), length=60, width=24, rotation=90 deg)
    }
    hole bell {
        a = Circle(center=(-5, -148), diameter=4)
        b = Circle(center=(5, -148), diameter=4)
    }
    bell_holes = LinearPattern(bell, bells, (0, -25))
    drawing paw {
        pad = Ellipse(center=(0, -78), rx=11, ry=9, fill=true)
        for i in range(4) {
            toe = Ellipse(center=(19 * cos(toe_angle(i)), -78 + 19 * sin(toe_angle(i))), rx=3.8,
                          ry=5, rotation=toe_angle(i) - 90 deg, fill=true)
        }
    }
    drawing words {
        ring = Text("RING", position=(0, -108), size=9, font="sans:Bold", fill=true)
        out = Text("TO GO OUT", position=(0, -122), size=6, font="sans:Bold", fill=true)
    }

    assert strip.bb.width == 70 mm, "70 wide"
    assert strip.bb.height == 300 mm, "300 long"
    assert strip.bb.top - handle.s.bb.top == 15 mm, "opening 15 below the top"
    assert handle.s.bb.width == 24 mm and handle.s.bb.height == 60 mm, "opening 24 x 60"
    assert len(bell_holes) == 5, "five bells"
    assert bell_holes[0].b.center.x - bell_holes[0].a.center.x == 10 mm, "holes 10 apart"
    assert bell_holes[0].a.center.y - bell_holes[1].a.center.y == 25 mm, "pairs 25 apart"
    assert bell_holes[4].a.center.y - 2 mm - strip.bb.bottom == 15 mm, "lowest pair 15 up"
    assert distance(words, bell_holes) >= 5 mm, "words clear of the bells"
    assert distance(paw.toe[1], paw.toe[2]) >= 1 mm, "toes apart"
    assert distance(paw.toe[0], paw.toe[1]) >= 1 mm, "toes apart"
    assert distance(paw.toe[1], paw.pad) >= 2 mm, "toes off the pad"
}
