# Request (garden): a small auricula theatre (a stepped shelf that shows off potted
# primulas) to hang on the shed wall, from 6 mm exterior ply, cut on a 900 x 600 mm bed.
# - Back board 420 mm wide, straight sides 360 mm tall, then an arched top rising to 420 mm
#   at the middle (a circular segment). Two keyholes (9 mm head, 4.5 mm shank, 12 mm long)
#   at 330 mm up, 150 mm either side of the middle. "AURICULA" engraved filled (serif bold,
#   18 mm) with its baseline at 375 mm, centred.
# - Two stepped sides 180 mm deep: a front step 140 mm high and a back step 260 mm high, each
#   90 mm deep; their two outer step corners rounded R10. Each side is glued into the back by
#   two 40 mm tenons along its 260 mm back edge; the sides' outer faces are 200 mm either
#   side of the middle (10 mm in from the back board's edges).
# - Two shelves 90 mm deep with their top faces at 120 mm (front) and 240 mm (back), 20 mm
#   below the step tops (the steps make a lip at each end); 388 mm between the sides, with
#   two 20 mm through tenons at each end. Pots of 8 cm fit on a shelf.

import "std/joints.aidl"
import "std/plates.aidl"

thickness 6 mm

t = 6 mm
back_w = 420 mm
back_h = 360 mm
arch_top = 420 mm
side_depth = 180 mm
step_d = 90 mm
step1 = 140 mm
step2 = 260 mm
lip = 20 mm
inner = 388 mm

# the arch: a circle through both shoulders and the crown
rise = arch_top - back_h
arch_r = ((back_w / 2) ** 2 + rise ** 2) / (2 * rise)

def side() -> solid {
    body = Polygon([(-t, 0), (side_depth, 0), (side_depth, step1), (step_d, step1),
                    (step_d, step2), (-t, step2)])
    Fillet(body.points[2], 10 mm)
    Fillet(body.points[4], 10 mm)
    tenons = tab_and_slot(part="tab", length=step2, thickness=t, tabs=2, tab=40 mm, screw=0,
                          rotation=90 deg, cx=-t, cy=step2 / 2)
    m1 = tab_and_slot(part="slot", length=step_d, thickness=t, tabs=2, tab=20 mm, screw=0,
                      cx=step_d + step_d / 2, cy=step1 - lip - t / 2)
    m2 = tab_and_slot(part="slot", length=step_d, thickness=t, tabs=2, tab=20 mm, screw=0,
                      cx=step_d / 2, cy=step2 - lip - t / 2)
    Fixed(body)
}

def shelf() -> solid {
    board = Rectangle(center=(0, 0), width=inner + 2 * t, height=step_d)
    left_end = tab_and_slot(part="tab", length=step_d, thickness=t, tabs=2, tab=20 mm, screw=0,
                            rotation=90 deg, cx=-(inner / 2 + t), cy=0)
    right_end = tab_and_slot(part="tab", length=step_d, thickness=t, tabs=2, tab=20 mm, screw=0,
                             rotation=-90 deg, cx=inner / 2 + t, cy=0)
    Fixed(board)
}

assembly theatre {
    solid back {
        body = Rectangle(bottom_left=(-back_w / 2, 0), width=back_w, height=back_h)
        crown = Intersect(Circle(center=(0, arch_top - arch_r), radius=arch_r),
                          Rectangle(bottom_left=(-back_w / 2, back_h - 10), width=back_w,
                                    height=rise + 20))
        left_m = tab_and_slot(part="slot", length=step2, thickness=t, tabs=2, tab=40 mm,
                              screw=0, rotation=90 deg, cx=-(inner / 2 + t / 2), cy=step2 / 2)
        right_m = tab_and_slot(part="slot", length=step2, thickness=t, tabs=2, tab=40 mm,
                               screw=0, rotation=90 deg, cx=inner / 2 + t / 2, cy=step2 / 2)
        hang_l = keyhole(head=9 mm, slot_width=4.5 mm, length=12 mm, cx=-150 mm, cy=330 mm)
        hang_r = keyhole(head=9 mm, slot_width=4.5 mm, length=12 mm, cx=150 mm, cy=330 mm)
        drawing name {
            word = Text("AURICULA", position=(0, 375), size=18, font="serif:Bold", fill=true)
        }
        Fixed(body)
    }
    lside = side()
    rside = side()
    shelf1 = shelf()
    shelf2 = shelf()

    # flat on the sheet
    RightOf(lside, back, gap=10)
    AlignBottom(lside, back)
    RightOf(rside, lside, gap=10)
    AlignBottom(rside, back)
    Above(shelf1, back, gap=10)
    AlignLeft(shelf1, back)
    Above(shelf2, shelf1, gap=10)
    AlignLeft(shelf2, back)

    # assembled: x across, -y to the front, z up; the back's front face at y = 0
    Place(back, position=(0, t, 0), face="front", up="up")
    Place(lside, position=(-inner / 2, 0, 0), face="left", up="up")
    Place(rside, position=(inner / 2 + t, 0, 0), face="left", up="up")
    Place(shelf1, position=(0, -(step_d + step_d / 2), step1 - lip - t), face="up")
    Place(shelf2, position=(0, -step_d / 2, step2 - lip - t), face="up")

    # the request's numbers
    assert back.body.bb.width == 420 mm, "back 420 wide"
    assert back.bb.top - back.body.bb.bottom == 420 mm, "arch crown at 420"
    assert back.body.bb.height == 360 mm, "straight sides 360"
    assert lside.body.bb.right - (lside.body.bb.left + t) == 180 mm, "sides 180 deep"
    assert lside.m1.slot[0].bb.top - lside.body.bb.bottom == 120 mm, "front shelf top at 120"
    assert lside.m2.slot[0].bb.top - lside.body.bb.bottom == 240 mm, "back shelf top at 240"
    assert step1 - (lside.m1.slot[0].bb.top - lside.body.bb.bottom) == 20 mm, "20 mm lip"
    assert step2 - (lside.m2.slot[0].bb.top - lside.body.bb.bottom) == 20 mm, "20 mm lip"
    assert shelf1.board.bb.width - 2 * t == 388 mm, "388 between the sides"
    assert shelf1.board.bb.height >= 80 mm, "an 8 cm pot stands on a shelf"
    assert inner / 2 + t == 200 mm, "sides' outer faces 200 from the middle"
    assert back.body.bb.right - (inner / 2 + t) == 10 mm, "sides 10 in from the back's edges"
    assert back.hang_r.head_hole.center.x - back.body.bb.center_x == 150 mm, "keyholes 150 out"
    assert back.hang_r.head_hole.center.y - back.body.bb.bottom == 330 mm, "keyholes at 330"
    assert back.name.word.position.y - back.body.bb.bottom == 375 mm, "name baseline at 375"
    assert back.name.bb.top <= back.bb.top - 10 mm, "name under the crown"
    assert distance(back.name, back.hang_l) >= 10 mm, "name clear of the keyholes"
    assert len(lside.tenons.gap) == 3, "two tenons on the back edge"
}
