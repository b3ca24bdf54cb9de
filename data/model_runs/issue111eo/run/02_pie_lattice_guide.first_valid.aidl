# Request: a lattice-pie cutting guide in 3 mm clear acrylic (food-safe, washable). A disc
# 260 mm across (a pastry sheet for a 23 cm / 9 in pie dish) laid on the rolled pastry;
# parallel knife slots 4 mm wide on a 20 mm pitch, one through the centre, as many as fit
# with at least 28 mm of rim above the top slot and below the bottom one (11 slots); each
# slot stops 15 mm short of the rim so the disc stays one piece. A round hanging tab on top,
# 32 mm across, with a 10 mm hole, its joins to the disc rounded R5. Engraved under the slots:
# "LATTICE GUIDE" and "20 mm STRIPS".

thickness 3 mm

param pitch = 20 mm, min = 14 mm, max = 30 mm
disc_d = 260 mm
r = disc_d / 2
slot_w = 4 mm
margin = 15 mm
n = 2 * floor(100 mm / pitch) + 1

# length of the chord at height y of the disc
def chord(y) = 2 * sqrt(r * r - y * y)
# height of slot i
def slot_y(i) = (i - (n - 1) / 2) * pitch

solid guide {
    disc = Circle(center=(0, 0), diameter=disc_d)
    tab = Circle(center=(0, r + 6 mm), diameter=32)
    Fixed(disc)
    Fixed(tab)
    Fillet([disc, tab], 5)

    hole hang { c = Circle(center=(0, r + 6 mm), diameter=10) }
    Concentric(hang.c, tab)

    hole slots {
        for i in range(n) {
            # the slot's outer edge is the shorter chord: length from it, less the margins
            s = Slot(center=(0, slot_y(i)), length=chord(abs(slot_y(i)) + slot_w / 2) - 2 * margin,
                     width=slot_w)
        }
    }

    drawing label {
        title = Text("LATTICE GUIDE", position=(0, -r + 19 mm), size=6, valign="middle")
        strips = Text(f"{pitch:.0f} mm STRIPS", position=(0, -r + 10 mm), size=5, valign="middle")
    }

    # the request's numbers
    assert disc.diameter == 260 mm
    assert len(slots.s) == 11, "11 slots at a 20 mm pitch"
    assert slots.s[1].center.y - slots.s[0].center.y == 20 mm
    assert slots.s[0].width == 4 mm
    assert slots.s[5].center.y == disc.center.y, "one slot through the centre"
    assert disc.bb.top - slots.s[10].bb.top >= 28 mm and slots.s[0].bb.bottom - disc.bb.bottom >= 28 mm
    assert tab.diameter == 32 mm and hang.c.diameter == 10 mm
    assert distance(label, slots) >= 3 mm, "text clear of the slots"
    assert distance(label.title, label.strips) >= 1 mm
}
