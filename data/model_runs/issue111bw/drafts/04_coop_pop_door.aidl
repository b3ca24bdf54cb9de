# Request (pets): "A sliding pop-hole door for my chicken coop, all 6 mm exterior ply. A back
# plate 280 x 520 mm (8 mm corners) with the pop hole: 180 wide, 220 tall, a round (semicircular)
# top, its bottom 25 mm above the plate's bottom edge. Over it a spacer frame the same size
# with a 211 x 490 window, its bottom 10 mm up, in which a 210 x 250 door slides (0.5 mm play
# each side); the frame's top bar stops the raised door once its bottom has cleared the hole.
# Two 50 mm cover strips, full height, hold the door in, overlapping its edges by 15 mm. Four
# M4 countersunk screws (9 mm heads) per side, 115 mm off the centre line at 40, 180, 340 and
# 480 mm up, go through cover, frame and plate into the coop. The door has a 12 mm rope hole
# 15 mm below its top edge and 'CLUCK INN' engraved filled, bold, 20 mm high, in its middle."

thickness 6 mm

screw_x = 115 mm
screw_ys = [40 mm, 180 mm, 340 mm, 480 mm]

# every part is drawn in one frame: x = 0 the centre line, y = 0 the plate's bottom edge

def screw_row(side=1) -> hole {
    for k in range(4) { c = Circle(center=(side * screw_x, screw_ys[k]), diameter=4.5) }
}

def cover(side=1) -> solid {
    strip = Rectangle(bottom_left=(side * screw_x - 25, 0), width=50, height=520)
    screws = screw_row(side=side)
    Countersink(screws, diameter=9 mm)
}

assembly pop_door {
    solid plate {
        body = RoundedRectangle(bottom_left=(-140, 0), width=280, height=520, corner_radius=8)
        hole pop {
            lower = Rectangle(bottom_left=(-90, 25), width=180, height=130)
            arch = Circle(center=(0, 155), radius=90)
        }
        left_screws = screw_row(side=-1)
        right_screws = screw_row(side=1)
    }

    solid frame {
        body = RoundedRectangle(bottom_left=(-140, 0), width=280, height=520, corner_radius=8)
        hole window { w = Rectangle(bottom_left=(-105.5, 10), width=211, height=490) }
        left_screws = screw_row(side=-1)
        right_screws = screw_row(side=1)
    }

    solid door {
        leaf = Rectangle(bottom_left=(-105, 10), width=210, height=250)
        hole rope { c = Circle(center=(0, 245), diameter=12) }
        drawing name {
            t = Text("CLUCK INN", position=(0, 135), size=20, font="sans:Bold", valign="middle",
                     fill=true)
        }
    }

    left_cover = cover(side=-1)
    right_cover = cover(side=1)

    # laid out flat in a row
    RightOf(frame, plate, gap=10)
    RightOf(door, frame, gap=10)
    RightOf(left_cover, door, gap=10)
    RightOf(right_cover, left_cover, gap=10)
    AlignBottom(frame, plate)
    AlignBottom(door, plate)
    AlignBottom(left_cover, plate)
    AlignBottom(right_cover, plate)

    # assembled, as written: plate on the coop wall (z = 0), frame and door on it, covers on top
    Place(plate, position=(0, 0, 0))
    Place(frame, position=(0, 0, 6))
    Place(door, position=(0, 0, 6))
    Place(left_cover, position=(0, 0, 12))
    Place(right_cover, position=(0, 0, 12))

    # the request's numbers (as differences within each part)
    assert plate.body.bb.width == 280 mm and plate.body.bb.height == 520 mm, "plate 280 x 520"
    assert plate.pop.bb.width == 180 mm and plate.pop.bb.height == 220 mm, "hole 180 x 220"
    assert plate.pop.bb.bottom - plate.body.bb.bottom == 25 mm, "hole 25 mm up"
    assert frame.window.w.width == 211 mm and frame.window.w.height == 490 mm, "window 211 x 490"
    assert frame.window.w.bb.bottom - frame.body.bb.bottom == 10 mm, "window 10 mm up"
    assert door.leaf.width == 210 mm and door.leaf.height == 250 mm, "door 210 x 250"
    assert (frame.window.w.width - door.leaf.width) / 2 == 0.5 mm, "0.5 mm play each side"
    # raised to the top bar, the door's bottom clears the hole's top
    assert (frame.window.w.bb.top - door.leaf.height) - frame.body.bb.bottom >= plate.pop.bb.top - plate.body.bb.bottom, "door clears the hole"
    assert left_cover.strip.width == 50 mm and left_cover.strip.height == 520 mm, "50 mm strips"
    # the covers overlap the door's edge by 15 mm (in the common frame as written)
    assert right_cover.strip.bb.left - 90 mm == 0 mm and door.leaf.width / 2 - 90 mm == 15 mm, "15 mm overlap"
    assert len(plate.left_screws.c) == 4 and len(right_cover.screws.c) == 4, "four screws a side"
    assert right_cover.screws.c[3].center.y - right_cover.strip.bb.bottom == 480 mm, "top screw 480 up"
    assert plate.right_screws.c[3].center.y - plate.body.bb.bottom == 480 mm, "plate's too"
    assert (right_cover.screws.c[0].center.x - right_cover.strip.bb.left ==
            plate.right_screws.c[0].center.x - plate.body.bb.left - 230 mm), "screws line up"
    assert door.rope.c.diameter == 12 mm, "12 mm rope hole"
    assert door.leaf.bb.top - door.rope.c.center.y == 15 mm, "15 below the top"
}
