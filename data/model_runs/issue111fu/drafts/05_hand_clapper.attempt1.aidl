# Request: a party hand clapper (noisemaker), 4 mm birch ply, three pieces on a 5 mm dowel:
# - a centre piece: a hand on a handle 120 mm long below the hand's wrist, 22 mm wide with
#   6 mm rounded corners at its end, the corners where it meets the wrist rounded 3 mm;
#   "HOORAY!" engraved up the handle, 10 mm letters;
# - two loose hands (the same hand, one turned over in use).
# The hand: a wrist 44 x 28 mm (8 mm corners), the pivot hole in its middle; a palm 60 x 50 mm
# (12 mm corners) above it, overlapping the wrist 4 mm; four fingers 13 mm wide, 1.5 mm
# apart, standing 40, 45, 42 and 34 mm above the palm's top (index to little), round-ended;
# a thumb 14 mm wide, round-ended, angled up and out at about 130 deg, its inside corners
# against the palm rounded 4 mm. Pivot holes: 5 mm in the centre piece (tight on the dowel),
# 5.6 mm in the loose hands (they swing). Stacked loose hand / centre / loose hand.

units mm
thickness 4 mm

T = 4 mm
LENGTHS = [40, 45, 42, 34]
PITCH = 13 mm + 1.5 mm

def hand(pivot=5 mm) -> solid {
    wrist = RoundedRectangle(center=(0, 0), width=44, height=28, corner_radius=8)
    palm = RoundedRectangle(bottom_left=(-30, 10), width=60, height=50, corner_radius=12)
    for i in range(4) {
        f = Slot(start=(-1.5 * PITCH + i * PITCH, 45),
                 end=(-1.5 * PITCH + i * PITCH, 60 + LENGTHS[i] - 6.5), width=13)
    }
    thumb = Slot(start=(-20, 26), end=(-40, 48), width=14)
    Fillet([thumb, palm], 4)
    hole pin { c = Circle(center=(0, 0), diameter=pivot) }
    assert palm.width == 60 mm and palm.height == 50 mm, "palm 60 x 50"
    assert wrist.top.midpoint.y - palm.bottom.midpoint.y == 4 mm, "palm overlaps the wrist 4 mm"
    assert len(f) == 4, "four fingers"
    assert f[1].bb.top - palm.bb.top == 45 mm, "middle finger 45 above the palm"
    assert f[3].bb.top - palm.bb.top == 34 mm, "little finger 34 above the palm"
    assert distance(f[0], f[1]) == 1.5 mm, "fingers 1.5 mm apart"
    assert thumb.width == 14 mm, "thumb 14 wide"
    assert pin.c.center.y == wrist.center.y, "pivot in the wrist's middle"
}

assembly clapper {
    solid centre {
        h = hand(pivot=5 mm)
        handle = RoundedRectangle(bottom_left=(-11, -134), width=22, height=126,
                                  corner_radius=6)
        Fillet([handle, h.wrist], 3)
        drawing cheer {
            t = Text("HOORAY!", position=(0, -75), size=10, rotation=90 deg, valign="middle")
        }
        assert h.wrist.bb.bottom - handle.bb.bottom == 120 mm, "handle 120 below the wrist"
        assert handle.width == 22 mm, "handle 22 wide"
        assert cheer.bb.bottom >= handle.bb.bottom + 5 mm, "words on the handle"
        assert cheer.bb.top <= h.wrist.bb.bottom - 3 mm, "words below the wrist"
    }
    left = hand(pivot=5.6 mm)
    right = hand(pivot=5.6 mm)

    RightOf(left, centre, gap=8)
    AlignTop(left, centre)
    RightOf(right, left, gap=8)
    AlignTop(right, left)

    # stacked on the dowel, flat: loose hand, centre, loose hand (the second turned over)
    Place(left, position=(0, 0, 0))
    Place(centre, position=(0, 0, T))
    Place(right, position=(0, 0, 3 * T), face="down", up="up")

    assert centre.h.pin.c.diameter == 5 mm, "5 mm pivot in the centre"
    assert left.pin.c.diameter == 5.6 mm, "5.6 mm pivot in the loose hands"
}
