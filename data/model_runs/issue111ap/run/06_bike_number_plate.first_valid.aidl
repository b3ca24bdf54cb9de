# Request (sport): a cyclocross handlebar number plate, 3 mm white acrylic (backed with a
# dark sheet). A 180 x 150 plate, top corners R20, bottom corners R10; race number "108"
# cut through in bold font outlines, 60 mm tall (counters kept by stencil bridges), centred
# 5 mm below the plate's middle, at most 150 mm wide; the rider's name "ANNA K." engraved
# (filled bold letters, 9 mm tall) centred 55 mm above the middle; three pairs of zip-tie
# slots (6 x 3 mm, the two slots of a pair 10 mm apart centre to centre, one above the other):
# two pairs at 60 mm left and right of the centre line at the top (pair centre 50 mm above
# the middle), one pair on the centre line at the bottom (pair centre 62 mm below the middle).

thickness 3 mm

def zip_pair() -> hole {
    upper = Slot(center=(0, 5), length=6, width=3)
    lower = Slot(center=(0, -5), length=6, width=3)
}

solid number_plate {
    plate = RoundedRectangle(center=(0, 0), width=180, height=150, corner_radii=[20, 20, 10, 10])
    Fixed(plate)

    hole number {
        digits = Text("108", (0, -5), size=60, font="sans:Bold", valign="middle", stencil=true,
                      max_width=150)
    }

    drawing name {
        t = Text("ANNA K.", (0, 55), size=9, font="sans:Bold", valign="middle", fill=true)
    }

    left_tie = zip_pair()
    right_tie = zip_pair()
    low_tie = zip_pair()
    At(left_tie.bb.center, plate.center, dx=-60, dy=50)
    At(right_tie.bb.center, plate.center, dx=60, dy=50)
    At(low_tie.bb.center, plate.center, dx=0, dy=-62)

    assert plate.bb.width == 180 mm and plate.bb.height == 150 mm, "180 x 150 plate"
    assert number.digits.size >= 55 mm, "number about 60 mm tall"
    assert number.bb.width <= 150 mm, "number at most 150 wide"
    assert abs(left_tie.upper.center.y - left_tie.lower.center.y - 10 mm) < 0.001 mm, "slots 10 mm apart"
    assert number.bb.top < name.bb.bottom - 5 mm, "number clear of the name"
    assert number.bb.bottom > low_tie.bb.top + 3 mm, "number clear of the bottom ties"
}
