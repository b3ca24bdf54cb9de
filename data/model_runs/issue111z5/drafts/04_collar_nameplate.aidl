# Pets: a slide-on name plate for a dog's collar (20 mm webbing), 3 mm acrylic. A plate 70 x 24 mm
# with R6 corners; at each end a slot 3 mm wide and 22 mm long (vertical), its centre 8 mm from
# that end, for the collar to thread through. Between the slots the name "BUDDY" in sans Bold,
# 10 mm cap height, engraved filled, centred 3 mm above the plate's middle (at most 40 mm wide),
# and the phone number "0151 234567" as single-stroke text 3 mm tall, its baseline 8 mm below
# the middle.
thickness 3 mm

solid nameplate {
    plate = RoundedRectangle(center=(0, 0), width=70, height=24, corner_radius=6)

    hole collar {
        left = Slot(center=(-35 + 8, 0), length=22, width=3, rotation=90)
        right = Slot(center=(35 - 8, 0), length=22, width=3, rotation=90)
    }

    drawing name {
        t = Text("BUDDY", position=(0, 3), size=10, font="sans:Bold", valign="middle",
                 fill=true, max_width=40)
    }
    drawing phone {
        t = Text("0151 234567", position=(0, -8), size=3)
    }

    assert plate.bb.width == 70 mm and plate.bb.height == 24 mm, "plate 70 x 24"
    assert collar.left.length == 22 mm and collar.left.width == 3 mm, "slots 3 x 22"
    assert collar.left.center.x - plate.bb.left == 8 mm, "left slot 8 from the end"
    assert plate.bb.right - collar.right.center.x == 8 mm, "right slot 8 from the end"
    # attempt 1: E0405, BUDDY at 10 mm is 49 mm wide, over the request's 40 mm limit: the fit
    # between the slots governs, the 10 mm cap height is the most it may be
    assert name.t.size <= 10 mm, "name at most 10 mm tall"
    assert name.t.bb.width <= 40 mm, "name at most 40 wide"
    assert name.t.bb.left > collar.left.bb.right and name.t.bb.right < collar.right.bb.left, "name between the slots"
    assert phone.t.bb.left > collar.left.bb.right and phone.t.bb.right < collar.right.bb.left, "number between the slots"
}
