# Request: a chicken feed trough with an anti-roost spinner, 6 mm exterior ply, bolted
# together (M4 bolts with captive nuts) so it comes apart for scrubbing.
# Inside: 400 mm long, 80 mm wide at the bottom, 80 mm deep, the two long sides leaning out
# at 20 deg. Bottom board and the two sides each carry 2 tabs 20 mm wide at both ends with an
# M4 T-slot between them, into mortises in two end plates. End plate: 140 wide at its base
# (26 mm below the trough floor), 200 wide at 95 mm up, a post 40 wide rising to 140 mm with a
# rounded top and a 13 mm hole at 120 mm for a 12 mm dowel that spins (so hens can't perch);
# a low arch 90 x 14 cut from the base leaves two feet. "HENS" engraved, filled bold, 14 mm,
# centred 40 mm up on each end plate's outer face.

import "std/joints.aidl"

units mm
thickness 6 mm

t = 6 mm
inner_len = 400 mm
floor_w = 80 mm
depth = 80 mm
lean = 20 deg
slant = depth / cos(lean)          # a side board's width along its slope
board_len = inner_len + 2 * t      # tabs run through the end plates

def side_board() -> solid {
    # frame: x along the trough, y up the slope (0 at the floor)
    body = Rectangle(bottom_left=(-board_len / 2, 0), width=board_len, height=slant)
    left_tabs = tab_and_slot(part="tab", length=slant, thickness=t, tabs=2, tab=20 mm, screw=4,
                             rotation=90 deg, cx=-board_len / 2, cy=slant / 2)
    right_tabs = tab_and_slot(part="tab", length=slant, thickness=t, tabs=2, tab=20 mm, screw=4,
                              rotation=-90 deg, cx=board_len / 2, cy=slant / 2)
}

def end_plate() -> solid {
    # frame: x across the trough, y up (0 = the trough's floor, the bottom board's top face)
    outline = Polygon([(-70, -26), (70, -26), (100, 95), (-100, 95)])
    post = RoundedRectangle(center=(0, 115), width=40, height=50, corner_radii=[20, 20, 0, 0])
    hole axle { c = Circle(center=(0, 120), diameter=13) }
    hole arch { e = Ellipse(center=(0, -26), rx=45, ry=14) }
    floor_slot = tab_and_slot(part="slot", length=floor_w, thickness=t, tabs=2, tab=20 mm,
                              screw=4, cx=0 mm, cy=-t / 2)
    # each side board's middle: halfway up its inner face, moved out by half its thickness
    right_slot = tab_and_slot(part="slot", length=slant, thickness=t, tabs=2, tab=20 mm, screw=4,
                              rotation=90 deg - lean,
                              cx=floor_w / 2 + slant / 2 * sin(lean) + t / 2 * cos(lean),
                              cy=slant / 2 * cos(lean) - t / 2 * sin(lean))
    left_slot = tab_and_slot(part="slot", length=slant, thickness=t, tabs=2, tab=20 mm, screw=4,
                             rotation=90 deg + lean,
                             cx=-(floor_w / 2 + slant / 2 * sin(lean) + t / 2 * cos(lean)),
                             cy=slant / 2 * cos(lean) - t / 2 * sin(lean))
    drawing name {
        word = Text("HENS", position=(0, 40), size=14, font="sans:Bold", valign="middle",
                    fill=true)
    }
}

assembly chicken_trough {
    solid floor {
        # frame: x along the trough, y across it
        body = Rectangle(center=(0, 0), width=board_len, height=floor_w)
        left_tabs = tab_and_slot(part="tab", length=floor_w, thickness=t, tabs=2, tab=20 mm,
                                 screw=4, rotation=90 deg, cx=-board_len / 2, cy=0 mm)
        right_tabs = tab_and_slot(part="tab", length=floor_w, thickness=t, tabs=2, tab=20 mm,
                                  screw=4, rotation=-90 deg, cx=board_len / 2, cy=0 mm)
    }
    right_side = side_board()
    left_side = side_board()
    right_end = end_plate()
    left_end = end_plate()

    # flat on the sheet
    Above(right_side, floor, gap=8)
    AlignLeft(right_side, floor)
    Above(left_side, right_side, gap=8)
    AlignLeft(left_side, floor)
    Below(right_end, floor, gap=8)
    AlignLeft(right_end, floor)
    RightOf(left_end, right_end, gap=8)
    AlignTop(left_end, right_end)

    # in 3D: floor's top face at z = 0, trough along x
    Place(floor, position=(0, 0, -t), face="up")
    Place(right_side, position=(0, floor_w / 2 + t * cos(lean), -t * sin(lean)),
          rotation=(90 deg - lean, 0, 0))
    Place(left_side, position=(0, -floor_w / 2, 0), rotation=(90 deg + lean, 0, 0))
    Place(right_end, position=(inner_len / 2, 0, 0), face="right", up="up")
    Place(left_end, position=(-inner_len / 2, 0, 0), face="left", up="up")

    # the request's numbers
    assert floor.body.bb.width - 2 * t == 400 mm, "400 long inside"
    assert floor.body.bb.height == 80 mm, "floor 80 wide"
    assert right_side.body.bb.height * cos(lean) == 80 mm, "80 deep"
    assert right_end.outline.bb.width == 200 mm, "end plate 200 wide"
    assert right_end.post.bb.top - right_end.outline.bb.bottom == 140 mm + 26 mm,
        "post top 140 above the floor (base 26 below it)"
    assert right_end.axle.c.center.y == 120 mm, "dowel hole at 120"
    assert right_end.axle.c.diameter == 13 mm, "13 mm hole for a 12 mm dowel"
}
