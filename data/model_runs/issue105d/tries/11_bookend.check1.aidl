# Bookend, two parts from 3 mm sheet: an upright 120 x 150 mm (top corners rounded 10 mm)
# with two vertical slots 3.2 x 20 mm on its centre line, their centres 30 and 80 mm above
# the bottom edge; and a right-triangle brace with legs 100 mm (upright) and 80 mm (base),
# carrying on its upright leg two tabs 3 x 20 mm that fit the slots (same heights).
param slot_w = 3.2 mm, min = 3 mm, max = 3.6 mm
thickness 3 mm

assembly bookend {
    solid upright {
        body = RoundedRectangle(center=(0, 75), width=120, height=150, corner_radii=[10, 10, 0, 0])
        hole slot_low { s = Rectangle(center=(0, 30), width=slot_w, height=20) }
        hole slot_high { s = Rectangle(center=(0, 80), width=slot_w, height=20) }
        At(slot_low.s.center, body.bb.bottom_left, dx=60, dy=30)
        At(slot_high.s.center, body.bb.bottom_left, dx=60, dy=80)
    }
    solid brace {
        tri = Triangle((100, 0), (180, 0), (100, 100))
        tab_low = Rectangle(center=(98.5, 30), width=3, height=20)
        tab_high = Rectangle(center=(98.5, 80), width=3, height=20)
        RightOf(tri, tab_low)
        At(tab_low.center, (tab_low.center.x, tri.bb.bottom + 30))
        At(tab_high.center, (tab_low.center.x, tri.bb.bottom + 80))
    }
    Gap(upright, brace, 15)
    AlignBottom(brace, upright)
    assert brace.tri.bb.height == 100 mm and brace.tri.bb.width == 80 mm, "legs 100 and 80"
    assert brace.tab_high.center.y - brace.tab_low.center.y == upright.slot_high.s.center.y - upright.slot_low.s.center.y, "tabs match slots"
    assert upright.body.bb.width == 120 mm and upright.body.bb.height == 150 mm, "upright 120 x 150"
}
