# Request (workshop): a wall rack for my three tape measures, cut from 6 mm birch ply.
# - Back plate 300 x 150 mm, corners r6, hung on two screws through keyholes (8 mm head,
#   4 mm shank, 10 mm slot up), 240 mm apart, their heads 25 mm below the top edge.
#   "TAPES" engraved 12 mm high, centred, between the keyholes.
# - A shelf 300 mm wide standing 60 mm out from the back plate, its top 110 mm above the
#   back plate's bottom edge; glued into the back plate by 3 tabs of 20 mm on its back edge.
#   The tapes hang by their belt clips over its front edge; "5 M", "8 M" and "10 M" engraved
#   on its top, 100 mm apart, 10 mm in from the front edge, 7 mm high.
# - Two right-triangle brackets under the shelf, their planes 130 mm either side of the
#   centre: 50 mm deep under the shelf, 80 mm tall down the back plate, each glued by one
#   20 mm tab into the back plate and one into the shelf.

import "std/joints.aidl"
import "std/plates.aidl"

thickness 6 mm

t = 6 mm
shelf_top = 110 mm          # above the back plate's bottom edge
bracket_x = 130 mm          # bracket mid-planes at +-130

# A bracket drawn in the plane of the rack's side view: x = out from the wall's surface
# (negative: forward), y = height above the back plate's bottom edge. Its back edge runs
# t into the back plate, its top edge t into the shelf, so the tabs' tips lie on x = 0 and
# y = shelf_top.
def bracket() -> solid {
    tri = Polygon([(0, shelf_top), (-(50 + t), shelf_top), (0, shelf_top - t - 80)])
    into_back = tab_and_slot(part="tab", length=86 mm, thickness=t, tabs=1, tab=20 mm,
                             screw=0, rotation=-90 deg, cx=0 mm, cy=shelf_top - 43 mm)
    into_shelf = tab_and_slot(part="tab", length=56 mm, thickness=t, tabs=1, tab=20 mm,
                              screw=0, rotation=0 deg, cx=-28 mm, cy=shelf_top)
}

assembly rack {
    solid back {
        plate = RoundedRectangle(center=(0, 75), width=300, height=150, corner_radius=6)
        kh_l = keyhole(head=8 mm, slot_width=4 mm, length=10 mm, direction=90 deg,
                       cx=-120 mm, cy=125 mm)
        kh_r = keyhole(head=8 mm, slot_width=4 mm, length=10 mm, direction=90 deg,
                       cx=120 mm, cy=125 mm)
        # the shelf's 3 tabs: its mid-plane is 3 mm under its top
        shelf_slots = tab_and_slot(part="slot", length=300 mm, thickness=t, tabs=3, tab=20 mm,
                                   screw=0, cx=0 mm, cy=shelf_top - t / 2)
        left_slot = tab_and_slot(part="slot", length=86 mm, thickness=t, tabs=1, tab=20 mm,
                                 screw=0, rotation=90 deg, cx=-bracket_x, cy=shelf_top - 43 mm)
        right_slot = tab_and_slot(part="slot", length=86 mm, thickness=t, tabs=1, tab=20 mm,
                                  screw=0, rotation=90 deg, cx=bracket_x, cy=shelf_top - 43 mm)
        drawing title {
            word = Text("TAPES", position=(0, 128), size=12, valign="middle")
        }
        Fixed(plate)
    }

    # the shelf in its own frame: back edge (tab tips) at y = 33, front edge at y = -33
    solid shelf {
        board = Rectangle(center=(0, 0), width=300, height=66)
        tabs = tab_and_slot(part="tab", length=300 mm, thickness=t, tabs=3, tab=20 mm,
                            screw=0, cx=0 mm, cy=33 mm)
        # the bracket's top edge runs from 56 mm in front of the wall to the wall:
        # in the shelf's frame y from -23 to 33, middle 5
        left_slot = tab_and_slot(part="slot", length=56 mm, thickness=t, tabs=1, tab=20 mm,
                                 screw=0, rotation=90 deg, cx=-bracket_x, cy=5 mm)
        right_slot = tab_and_slot(part="slot", length=56 mm, thickness=t, tabs=1, tab=20 mm,
                                  screw=0, rotation=90 deg, cx=bracket_x, cy=5 mm)
        drawing labels {
            for i in range(3) {
                lab = Text(["5 M", "8 M", "10 M"][i], position=(-100 + 100 * i, -23),
                           size=7, valign="middle")
            }
        }
        Fixed(board)
    }

    left_bracket = bracket()
    right_bracket = bracket()

    # flat on the sheet: shelf under the back plate, brackets beside it
    Below(shelf, back, gap=10)
    AlignCenterX(shelf, back)
    Below(left_bracket, shelf, gap=10)
    AlignLeft(left_bracket, shelf)
    RightOf(right_bracket, left_bracket, gap=10)
    AlignBottom(right_bracket, left_bracket)

    # in 3D: wall face is y = 0 .. -6 (the plate's engraved face forward), up is z
    Place(back, position=(0, 0, 0), rotation=(90 deg, 0, 0))
    Place(shelf, position=(0, -33, shelf_top - t), rotation=(0, 0, 0))
    # (x, y, z) -> (z, x, y): the bracket's x runs out from the wall, its y up, its
    # thickness along the rack's x
    Place(left_bracket, position=(-bracket_x - t / 2, 0, 0), rotation=(90 deg, 0, 90 deg))
    Place(right_bracket, position=(bracket_x - t / 2, 0, 0), rotation=(90 deg, 0, 90 deg))

    assert back.plate.width == 300 mm and back.plate.height == 150 mm
    assert back.kh_r.head_hole.center.x - back.kh_l.head_hole.center.x == 240 mm
    assert back.plate.bb.top - back.kh_l.head_hole.center.y == 25 mm
    assert shelf.board.height - t == 60 mm, "60 mm out from the back plate"
    assert len(shelf.tabs.gap) == 4, "3 tabs leave 4 gaps"
    assert shelf.labels.lab[2].position.x - shelf.labels.lab[0].position.x == 200 mm
}
