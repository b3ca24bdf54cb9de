# Request (camping): a knock-down two-board camp chair ("Viking" chair) in 18 mm exterior
# ply. Back board 380 x 850 mm, top corners R60; a through slot 200 x 40 mm (R5 corners)
# whose centre is 300 mm above the bottom edge; a 120 x 35 mm carrying slot 60 mm below the
# top; "BASE CAMP" engraved filled in bold sans 40 mm high, 140 mm below the top, with an
# engraved mountain outline under it. Seat board 560 mm long: a 380 x 400 mm seat (front
# corners R40) and a 196 x 160 mm tongue at the back (2 mm clear each side in the slot), its
# end corners R20; the seat's shoulders bear on the back board's face.

thickness 18 mm

board_w = 380 mm
back_h = 850 mm
slot_w = 200 mm
slot_h = 40 mm
slot_up = 300 mm
seat_len = 400 mm
tongue_w = 196 mm
tongue_len = 160 mm

assembly chair {
    solid back {
        board = RoundedRectangle(center=(0, back_h / 2), width=board_w, height=back_h,
                                 corner_radii=[60, 60, 0, 0])
        hole seat_slot {
            r = RoundedRectangle(center=(0, slot_up), width=slot_w, height=slot_h,
                                 corner_radius=5)
        }
        hole carry {
            s = Slot(center=(0, back_h - 60), length=120, width=35)
        }
        drawing badge {
            name = Text("BASE CAMP", position=(0, back_h - 140), size=40, font="sans:Bold",
                        valign="middle", fill=true)
            peaks = Polyline([(-120, back_h - 250), (-60, back_h - 190), (-25, back_h - 225),
                              (30, back_h - 170), (120, back_h - 250)])
        }
        assert seat_slot.r.center.y - board.bb.bottom == 300 mm, "slot centre 300 up"
        assert board.bb.top - carry.s.center.y == 60 mm, "carrying slot 60 below the top"
        assert board.bb.width == 380 mm and board.bb.height == 850 mm, "back 380 x 850"
    }

    solid seat {
        front = RoundedRectangle(bottom_left=(0, 0), width=seat_len, height=board_w,
                                 corner_radii=[40, 0, 0, 40])
        tongue = RoundedRectangle(bottom_left=(seat_len - 1, (board_w - tongue_w) / 2),
                                  width=tongue_len + 1, height=tongue_w,
                                  corner_radii=[0, 20, 20, 0])
        assert tongue.bb.right - front.bb.left == 560 mm, "seat board 560 long"
    }
    RightOf(seat, back, gap=20)
    AlignBottom(seat, back)

    assert slot_w - seat.tongue.bb.height == 2 * 2 mm, "tongue 2 mm clear each side"
    assert seat.front.bb.height > slot_w, "shoulders bear on the back's face"
}
