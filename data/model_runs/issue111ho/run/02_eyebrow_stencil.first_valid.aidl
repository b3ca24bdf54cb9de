# Request (bathroom): a card of three eyebrow stencils cut from 0.5 mm clear PET, to hold
# against the brow and fill in with powder. The card is 180 x 60 mm with 6 mm corners and
# a 6 mm hanging hole 10 mm in from the top-left corner. Three brow openings, each 50 mm
# from the blunt inner end to the pointed tail, centred 58 mm apart along the card and
# 8 mm above its middle: THIN (6 mm tall at the head, peak raised 4 mm), ARCH (9 mm,
# peak 7 mm) and SOFT (10 mm, peak 3 mm). Each name engraved 4 mm tall, 14 mm below the
# middle, under its brow.

units mm
thickness 0.5 mm

pitch = 58 mm
brow_y = 8 mm
label_y = -14 mm

# a brow opening: blunt head on the left, upper edge rising to a peak, sharp tail
def brow(x, y, h, arch) -> hole {
    s = Spline([(x - 25, y - h / 2),
                (x - 24, y + h / 2),
                (x - 5, y + h / 2 + 0.7 * arch),
                (x + 10, y + h / 2 + arch),
                (x + 25, y - h / 2 + 0.3 * arch),
                (x + 10, y + h / 2 + arch - 0.6 * h),
                (x - 5, y - h / 2 + 0.4 * arch)], closed=true, corners=[4])
}

solid card {
    body = RoundedRectangle(center=(0, 0), width=180, height=60, corner_radius=6)
    hole hang {
        c = Circle(center=(-80, 20), diameter=6)
    }
    thin = brow(x=-pitch, y=brow_y, h=6, arch=4)
    arch = brow(x=0, y=brow_y, h=9, arch=7)
    soft = brow(x=pitch, y=brow_y, h=10, arch=3)

    drawing names {
        a = Text("THIN", (-pitch, label_y), size=4)
        b = Text("ARCH", (0, label_y), size=4)
        c = Text("SOFT", (pitch, label_y), size=4)
    }

    assert body.bb.width == 180 mm and body.bb.height == 60 mm, "card 180 x 60"
    assert hang.c.center.x - body.bb.left == 10 mm, "hanging hole 10 mm in from the left"
    assert body.bb.top - hang.c.center.y == 10 mm, "hanging hole 10 mm down from the top"
    assert thin.s.points[4].x - thin.s.points[0].x == 50 mm, "brows 50 mm long"
    assert arch.s.points[4].x - arch.s.points[0].x == 50 mm, "brows 50 mm long"
    assert soft.s.points[4].x - soft.s.points[0].x == 50 mm, "brows 50 mm long"
    assert arch.s.points[0].x - thin.s.points[0].x == 58 mm, "58 mm apart"
    assert distance(names, thin) >= 3 mm, "THIN clear of its brow"
    assert distance(names, arch) >= 3 mm, "ARCH clear of its brow"
    assert distance(names, soft) >= 3 mm, "SOFT clear of its brow"
    assert distance(hang, thin) >= 3 mm, "hanging hole clear of the first brow"
    assert thin.bb.left - body.bb.left >= 5 mm, "material left of the first brow"
    assert body.bb.right - soft.bb.right >= 5 mm, "material right of the last brow"
}
