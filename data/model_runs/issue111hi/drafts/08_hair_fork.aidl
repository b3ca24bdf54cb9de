# Request (gifts): a two-prong hair fork for a bun, cut from 4 mm walnut ply as a
# gift. A rounded fan-shaped head 56 mm wide and about 47 mm tall above the
# prongs' root, with a heart cut out of it (two 9 mm circles 8 mm apart and a
# point 10 mm below their centres) and the initials "LM" engraved filled in
# bold serif, 7 mm capitals, below the heart. Two prongs 14 mm apart with a
# round crotch (7 mm radius), each 7 mm wide at the root tapering to 4 mm at
# its round tip, the tips' centres 100 mm below the root. Overall length
# between 150 and 160 mm.

thickness 4 mm

solid fork {
    # FIX after the first valid program: one Hull round both tips, cut by the
    # slot between the prongs, left each tip square on its inner side (a snag
    # in the hair) and the head pinched where it met the root. Now each prong is
    # its own Hull (round tip), a neck block joins them to the head, and the
    # crotch is a 7 mm round hole meeting the prongs' inner edges tangentially.
    head = Spline([(0, 55), (15, 52), (26, 42), (28, 30), (21, 17), (14, 8), (0, 8)],
                  closed=true, mirror="y")
    neck = Rectangle(corner=(-14, 0), opposite=(14, 14))
    right_prong = Hull(Circle(center=(10.5, 0), radius=3.5), Circle(center=(9, -100), radius=2))
    left_prong = Hull(Circle(center=(-10.5, 0), radius=3.5), Circle(center=(-9, -100), radius=2))
    hole gap {
        s = Circle(center=(0, 0), radius=7)
    }
    hole heart {
        left = Hull(Circle(center=(-4, 38), radius=4.5), Point(0, 28))
        right = Hull(Circle(center=(4, 38), radius=4.5), Point(0, 28))
    }
    drawing initials {
        t = Text("LM", position=(0, 17), size=7, valign="middle", font="serif:Bold",
                 fill=true)
    }

    assert head.points[3].x - head.points[9].x == 56 mm, "head 56 mm wide"
    assert right_prong.bb.left - left_prong.bb.right == 14 mm, "prongs 14 mm apart"
    assert right_prong.bb.width == 7 mm, "each prong 7 mm wide at the root"
    assert head.points[0].y - right_prong.bb.bottom >= 150 mm and head.points[0].y - right_prong.bb.bottom <= 160 mm,
        "150 to 160 mm long"
    assert distance(initials, heart) >= 3 mm, "initials clear of the heart"
    assert distance(initials, gap) >= 2 mm, "initials clear of the crotch"
    assert distance(heart, gap) >= 10 mm, "heart well clear of the crotch"
}
