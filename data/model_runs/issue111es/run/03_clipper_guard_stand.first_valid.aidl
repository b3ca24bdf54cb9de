# Request: "A stand for the eight guide combs of my hair clippers, for the bathroom shelf,
# in 3 mm clear acrylic. A deck 200 x 90 mm (corners R5) stands 60 mm tall (top of deck
# above the shelf) on two end panels, which stand on a base 200 x 90 mm (R5) that catches
# the hair. The deck has eight slots 62 x 9 mm with round ends, running front to back on a
# 20 mm pitch, the combs dropping in teeth down. In front of each slot engrave its number
# #1 to #8 (5 mm tall) and under it the cutting length: 3, 6, 10, 13, 16, 19, 22, 25 mm
# (3 mm tall), each label at least 2 mm clear of its slot. The end panels are 90 mm deep
# and stand 180 mm apart centre to centre (at x = +-90 from the middle); each is glued into
# the deck and the base with two 15 mm tabs (mortises 0.1 mm over size). Kerf 0.1 mm."

import "std/joints.aidl"

units mm
t = 3 mm
thickness t
kerf 0.1 mm

len_x = 200 mm
depth = 90 mm
height = 60 mm
pitch = 20 mm
guards = 8
cut_mm = [3, 6, 10, 13, 16, 19, 22, 25]
side_x = 90 mm
tab_w = 15 mm
fit = 0.1 mm

def plate_with_mortises() -> solid {
    body = RoundedRectangle(center=(0, 0), width=len_x, height=depth, corner_radius=5 mm)
    left = tab_and_slot(part="slot", length=depth, thickness=t, tabs=2, tab=tab_w, screw=0,
                        clearance=fit, rotation=90 deg, cx=-side_x, cy=0 mm)
    right = tab_and_slot(part="slot", length=depth, thickness=t, tabs=2, tab=tab_w, screw=0,
                         clearance=fit, rotation=90 deg, cx=side_x, cy=0 mm)
}

def end_panel() -> solid {
    body = Rectangle(bottom_left=(-depth / 2, 0), width=depth, height=height)
    top = tab_and_slot(part="tab", length=depth, thickness=t, tabs=2, tab=tab_w, screw=0,
                       cx=0 mm, cy=height)
    bottom = tab_and_slot(part="tab", length=depth, thickness=t, tabs=2, tab=tab_w, screw=0,
                          rotation=180 deg, cx=0 mm, cy=0 mm)
}

assembly guard_stand {
    deck = plate_with_mortises()
    base = plate_with_mortises()
    left = end_panel()
    right = end_panel()

    # the deck's comb slots and their labels
    hole g {
        s = Slot(center=(-(guards - 1) * pitch / 2, 5 mm), length=62 mm, width=9 mm, rotation=90 deg)
    }
    CutInto(g, deck)
    row = LinearPattern(g, guards, (pitch, 0))
    drawing labels {
        for i in range(guards) {
            n = Text(f"#{i + 1}", position=(-(guards - 1) * pitch / 2 + i * pitch, -32 mm), size=5,
                     valign="middle")
            l = Text(f"{cut_mm[i]} mm", position=(-(guards - 1) * pitch / 2 + i * pitch, -39.5 mm),
                     size=3, valign="middle")
        }
    }
    CutInto(labels, deck)

    # on the sheet
    Below(base, deck, gap=5 mm)
    AlignLeft(base, deck)
    RightOf(left, deck, gap=5 mm)
    AlignTop(left, deck)
    Below(right, left, gap=5 mm)
    AlignLeft(right, left)

    # in 3D: base on the shelf, ends at x = +-90, deck on top
    Place(base, position=(0, 0, 0))
    Place(deck, position=(0, 0, height - t))
    Place(right, position=(side_x - t / 2, 0, 0), face="right")
    Place(left, position=(-side_x + t / 2, 0, 0), face="left")

    # the request's numbers
    assert len(row) == 8 and len(cut_mm) == 8, "eight combs"
    assert row[1].s.center.x - row[0].s.center.x == 20 mm, "20 mm pitch"
    assert row[0].s.length == 62 mm and row[0].s.width == 9 mm, "slots 62 x 9"
    assert deck.body.bb.width == 200 mm and deck.body.bb.height == 90 mm, "deck 200 x 90"
    assert left.body.bb.height == 60 mm, "deck top 60 mm above the shelf"
    assert deck.right.slot[0].bb.center_x - deck.left.slot[0].bb.center_x == 180 mm, "ends 180 mm apart"
    for i in range(guards) {
        assert distance(labels.n[i], row[i].s) >= 2 mm, "number clear of its slot"
        assert abs(labels.n[i].position.x - row[i].s.center.x) < 0.01 mm, "number under its slot"
        assert labels.l[i].bb.bottom - deck.body.bb.bottom >= 3 mm, "length label on the deck"
    }
    assert deck.left.slot[0].bb.right + 5 mm <= row[0].s.bb.left, "mortise clear of the first comb slot"
}
