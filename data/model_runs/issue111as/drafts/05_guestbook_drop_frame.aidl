# Request (parties): a drop-top guest book frame for a wedding: guests write on small wooden
# hearts and drop them into the frame through a slot in its top. Five layers 250 x 300 mm with
# 6 mm rounded corners, screwed together by four M3 countersunk screws 8 mm in from each corner
# (3.4 mm holes, 6.5 mm countersinks on the front), 3 mm material each:
#  - back (ply): two keyholes (8 mm head, 4 mm slot, 10 mm long, upward) 40 mm below the top
#    and 60 mm in from each side;
#  - two spacers (ply): frames with 18 mm borders, and a 60 mm wide channel through the top
#    border at its middle (the drop slot, 6 mm deep through the two spacers);
#  - a clear acrylic window, the full 250 x 300 with the corner holes;
#  - the front (ply): an opening 200 x 210 mm with 10 mm rounded corners, 25 mm borders at the
#    sides and 45 mm at top and bottom; "DROP A HEART" as filled bold letters 14 mm tall in the
#    middle of the top border, "ANNA & TOM  12.06.2027" as engraved serif outlines 10 mm tall
#    in the middle of the bottom border.
# Twelve hearts (3 x 4) about 34 x 30 mm, 3 mm ply, to fit the slot. Assembled in 3D.

import "std/plates.aidl"

thickness 3 mm

mat = 3 mm
param frame_w = 250 mm, min = 180 mm, max = 400 mm
param frame_h = 300 mm, min = 220 mm, max = 450 mm
corner_r = 6 mm
screw_inset = 8 mm
border = 18 mm
drop_w = 60 mm

def heart() -> solid {
    lobe_l = Hull(Circle(center=(-8, 5), radius=9), Point(0, -16))
    lobe_r = Hull(Circle(center=(8, 5), radius=9), Point(0, -16))
}

def spacer() -> solid {
    plate = RoundedRectangle(center=(0, 0), width=frame_w, height=frame_h, corner_radius=corner_r)
    hole window {
        r = Rectangle(center=(0, 0), width=frame_w - 2 * border, height=frame_h - 2 * border)
    }
    hole channel {
        # through the top border into the window, run 1 mm past both
        r = Rectangle(center=(0, frame_h / 2 - border / 2), width=drop_w, height=border + 2 mm,
                      overrun=true)
    }
    hole screw { c = Circle(center=(0, 0), diameter=3.4) }
    screws = CornerPattern(screw, plate, inset=screw_inset)
}

assembly guestbook {
    solid back {
        plate = RoundedRectangle(center=(0, 0), width=frame_w, height=frame_h, corner_radius=corner_r)
        hole screw { c = Circle(center=(0, 0), diameter=3.4) }
        screws = CornerPattern(screw, plate, inset=screw_inset)
        hang_l = keyhole(head=8 mm, slot_width=4 mm, length=10 mm, direction=90 deg,
                         cx=-frame_w / 2 + 60 mm, cy=frame_h / 2 - 40 mm)
        hang_r = keyhole(head=8 mm, slot_width=4 mm, length=10 mm, direction=90 deg,
                         cx=frame_w / 2 - 60 mm, cy=frame_h / 2 - 40 mm)
    }
    spacer_a = spacer()
    spacer_b = spacer()
    solid window {
        plate = RoundedRectangle(center=(0, 0), width=frame_w, height=frame_h, corner_radius=corner_r)
        hole screw { c = Circle(center=(0, 0), diameter=3.4) }
        screws = CornerPattern(screw, plate, inset=screw_inset)
    }
    solid front {
        plate = RoundedRectangle(center=(0, 0), width=frame_w, height=frame_h, corner_radius=corner_r)
        hole opening {
            r = RoundedRectangle(center=(0, 0), width=frame_w - 2 * 25 mm, height=frame_h - 2 * 45 mm,
                                 corner_radius=10)
        }
        hole screw { c = Circle(center=(0, 0), diameter=3.4) }
        screws = CornerPattern(screw, plate, inset=screw_inset)
        Countersink(screws, diameter=6.5)
        drawing words {
            top = Text("DROP A HEART", position=(0, frame_h / 2 - 22.5 mm), size=14,
                       font="sans:Bold", valign="middle", fill=true)
            names = Text("ANNA & TOM  12.06.2027", position=(0, -frame_h / 2 + 22.5 mm), size=10,
                         font="serif", valign="middle")
        }
    }
    h0 = heart()
    hearts = GridPattern(h0, 3, 4, (40, 36))

    # on the sheet
    RightOf(spacer_a, back, gap=8)
    AlignTop(spacer_a, back)
    RightOf(spacer_b, spacer_a, gap=8)
    AlignTop(spacer_b, back)
    Below(window, back, gap=8)
    AlignLeft(window, back)
    RightOf(front, window, gap=8)
    AlignTop(front, window)
    RightOf(h0, front, gap=12)
    AlignBottom(h0, front)

    # assembled, back to front
    Place(back, position=(0, 0, 0))
    Place(spacer_a, position=(0, 0, mat))
    Place(spacer_b, position=(0, 0, 2 * mat))
    Place(window, position=(0, 0, 3 * mat))
    Place(front, position=(0, 0, 4 * mat))

    # the request's numbers
    assert back.plate.bb.width == 250 mm and back.plate.bb.height == 300 mm, "250 x 300"
    assert len(front.screws) == 4, "four screws"
    assert front.screws[0].c.center.x - front.plate.bb.left == 8 mm, "screws 8 mm in"
    assert front.plate.bb.top - front.screws[2].c.center.y == 8 mm, "screws 8 mm down"
    assert back.plate.bb.top - back.hang_l.head_hole.center.y == 40 mm, "keyholes 40 mm below the top"
    assert back.hang_l.head_hole.center.x - back.plate.bb.left == 60 mm, "left keyhole 60 mm in"
    assert back.plate.bb.right - back.hang_r.head_hole.center.x == 60 mm, "right keyhole 60 mm in"
    assert spacer_a.window.r.bb.left - spacer_a.plate.bb.left == 18 mm, "spacer borders 18 mm"
    assert spacer_a.channel.r.bb.width == 60 mm, "drop slot 60 mm wide"
    assert front.opening.r.bb.width == 200 mm and front.opening.r.bb.height == 210 mm, "opening 200 x 210"
    assert front.opening.r.bb.bottom - front.plate.bb.bottom == 45 mm, "45 mm bottom border"
    assert front.words.top.size == 14 mm and front.words.names.size == 10 mm, "text sizes"
    assert len(hearts) == 12, "twelve hearts"
    assert h0.bb.width < drop_w - 10 mm, "a heart passes the slot with room"
    assert mat < 2 * mat, "a heart is thinner than the two spacers"
    assert front.words.names.bb.width < front.plate.bb.width - 2 * 25 mm, "names fit the bottom border"
}
