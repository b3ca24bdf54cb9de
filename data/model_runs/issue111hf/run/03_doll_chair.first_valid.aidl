# Request (toys): a chair for an 18-inch doll, flat-packed from 6 mm birch ply and glued with
# tab-and-slot joints (slots 0.1 mm oversize).
# - two sides, 140 mm deep: a back post 20 mm wide and 290 mm tall with its top corners
#   rounded 8 mm; a front leg 20 mm wide and 130 mm tall (its top front corner rounded 5 mm);
#   a rail joining them from 100 to 130 mm high, the corners under the rail rounded 6 mm.
# - a seat 127 mm deep (from the backrest's front face to the front legs' front edge),
#   130 mm between the sides, its top 124 mm above the floor, with two 30 mm tabs through
#   each side.
# - a backrest 130 mm between the sides, standing in the middle of the back posts, from the
#   seat's top up to 280 mm, with two 30 mm tabs into each back post; a heart 34 mm wide cut
#   out near its top, and the doll's name ROSIE engraved in filled bold letters 14 mm tall
#   below the heart.
# - a front stretcher 25 mm tall between the front legs, 20 mm off the floor, in the middle
#   of the legs, one 15 mm tab at each end.
# The five parts laid out 10 mm apart.

import "std/joints.aidl"

units mm
thickness 6 mm

t = 6 mm
depth = 140 mm
seat_top = 124 mm
seat_depth = 127 mm
inner_w = 130 mm
back_top = 280 mm
back_mid = 10 mm          # the backrest's mid-plane: the middle of the 20 mm back post
leg_mid = 130 mm          # the stretcher's mid-plane: the middle of the front leg

def side() -> solid {
    profile = Polygon([(0, 0), (20, 0), (20, 100), (120, 100), (120, 0), (140, 0), (140, 130),
                       (20, 130), (20, 290), (0, 290)])
    seat_slots = tab_and_slot(part="slot", length=seat_depth, thickness=t, tabs=2, tab=30,
                              screw=0, clearance=0.1, rotation=0 deg,
                              cx=back_mid + t / 2 + seat_depth / 2, cy=seat_top - t / 2)
    back_slots = tab_and_slot(part="slot", length=back_top - seat_top, thickness=t, tabs=2,
                              tab=30, screw=0, clearance=0.1, rotation=90 deg,
                              cx=back_mid, cy=(seat_top + back_top) / 2)
    stretcher_slot = tab_and_slot(part="slot", length=25, thickness=t, tabs=1, tab=15,
                                  screw=0, clearance=0.1, rotation=90 deg,
                                  cx=leg_mid, cy=20 + 25 / 2)
    Fillet([(0, 290), (20, 290)], 8)
    Fillet((140, 130), 5)
    Fillet([(20, 100), (120, 100)], 6)

    assert profile.bb.width == 140 mm and profile.bb.height == 290 mm, "140 deep, post 290 tall"
    assert ((seat_slots.slot[0].bb.top + seat_slots.slot[0].bb.bottom) / 2 + 3 mm
            - profile.bb.bottom == 124 mm), "seat top 124 mm above the floor"
    assert ((stretcher_slot.slot[0].bb.top + stretcher_slot.slot[0].bb.bottom) / 2 - 12.5 mm
            - profile.bb.bottom == 20 mm), "stretcher 20 mm off the floor"
    assert back_slots.slot[1].bb.top <= 290 mm - 10 mm, "the back slots stay in the post"
}

assembly doll_chair {
    left_side = side()
    right_side = side()

    solid seat {
        board = Rectangle(center=(0, 0), width=inner_w + 2 * t, height=seat_depth)
        right_tabs = tab_and_slot(part="tab", length=seat_depth, thickness=t, tabs=2, tab=30,
                                  screw=0, rotation=-90 deg, cx=inner_w / 2 + t, cy=0)
        left_tabs = tab_and_slot(part="tab", length=seat_depth, thickness=t, tabs=2, tab=30,
                                 screw=0, rotation=90 deg, cx=-inner_w / 2 - t, cy=0)
        assert board.height == 127 mm, "seat 127 mm deep"
        assert board.width - 2 * t == 130 mm, "130 mm between the sides"
    }

    solid backrest {
        board = Rectangle(center=(0, (back_top - seat_top) / 2), width=inner_w + 2 * t,
                          height=back_top - seat_top)
        right_tabs = tab_and_slot(part="tab", length=back_top - seat_top, thickness=t, tabs=2,
                                  tab=30, screw=0, rotation=-90 deg, cx=inner_w / 2 + t,
                                  cy=(back_top - seat_top) / 2)
        left_tabs = tab_and_slot(part="tab", length=back_top - seat_top, thickness=t, tabs=2,
                                 tab=30, screw=0, rotation=90 deg, cx=-inner_w / 2 - t,
                                 cy=(back_top - seat_top) / 2)
        hole heart {
            lobe_l = Hull(Circle(center=(-8, 115), radius=9), Point(0, 94))
            lobe_r = Hull(Circle(center=(8, 115), radius=9), Point(0, 94))
        }
        drawing name {
            n = Text("ROSIE", position=(0, 60), size=14, font="sans:Bold", valign="middle",
                     fill=true)
        }
        assert board.height == 280 mm - 124 mm, "from the seat's top to 280 mm"
        assert heart.bb.width == 34 mm, "heart 34 mm wide"
        assert distance(name, heart) >= 8 mm, "the name sits clear below the heart"
        assert name.bb.width <= inner_w - 20 mm, "the name fits between the posts"
    }

    solid stretcher {
        board = Rectangle(center=(0, 0), width=inner_w + 2 * t, height=25)
        right_tab = tab_and_slot(part="tab", length=25, thickness=t, tabs=1, tab=15, screw=0,
                                 rotation=-90 deg, cx=inner_w / 2 + t, cy=0)
        left_tab = tab_and_slot(part="tab", length=25, thickness=t, tabs=1, tab=15, screw=0,
                                rotation=90 deg, cx=-inner_w / 2 - t, cy=0)
    }

    RightOf(right_side, left_side, gap=10)
    AlignBottom(right_side, left_side)
    RightOf(seat, right_side, gap=10)
    AlignBottom(seat, right_side)
    RightOf(backrest, seat, gap=10)
    AlignBottom(backrest, seat)
    Above(stretcher, seat, gap=10)
    AlignLeft(stretcher, seat)
}
