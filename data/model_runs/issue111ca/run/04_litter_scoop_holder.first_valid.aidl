# Request (pets): a wall holder for the cat-litter scoop, from 6 mm ply. A back plate 150 mm
# wide and 310 mm tall, its top with two cat ears rising 35 mm above it, hung on two screws by
# keyholes (9 mm head, 4.5 mm slot, 12 mm long) 80 mm apart, 40 mm below the top edge; a
# 12.5 mm hole on the centre line 40 mm above the plate's middle for a dowel that carries a
# roll of poop bags. At its foot an open pocket for the scoop, 130 mm wide, 60 mm deep from
# the wall and 110 mm tall outside, its bottom 10 mm above the plate's bottom edge: front,
# two sides and a bottom finger-jointed together (10 mm fingers), the sides and the bottom
# tenoned into the back plate (2 tabs each, glued); 2 x 5 drain holes of 6 mm, 20 mm apart,
# in the bottom; "SCOOP" (bold, filled, 20 mm) and a paw print engraved on the front.

import "std/joints.aidl"
import "std/plates.aidl"

thickness 6 mm

T = 6 mm
W = 130 mm        # pocket outside width
D = 60 mm         # pocket outside depth from the wall
H = 110 mm        # pocket outside height
plate_w = 150 mm
plate_h = 310 mm
foot = 10 mm      # plate below the pocket's bottom

def side_panel() -> solid {
    p = finger_panel(width=D + T, height=H, thickness=T, finger=10 mm, bottom="fingers",
                     right="slots", top="flat", left="flat")
    back = tab_and_slot(part="tab", length=H, thickness=T, tabs=2, tab=25 mm, screw=0,
                        rotation=90 deg, cx=-(D + T) / 2, cy=0)
}

assembly holder {
    solid plate {
        body = RoundedRectangle(center=(0, 0), width=plate_w, height=plate_h, corner_radius=10)
        left_ear = Hull(Circle(center=(-52, plate_h / 2 + 30), radius=5),
                        Point(-72, plate_h / 2 - 10), Point(-28, plate_h / 2 - 10))
        right_ear = Hull(Circle(center=(52, plate_h / 2 + 30), radius=5),
                         Point(72, plate_h / 2 - 10), Point(28, plate_h / 2 - 10))
        hang_l = keyhole(head=9 mm, slot_width=4.5 mm, length=12 mm, cx=-40, cy=plate_h / 2 - 40)
        hang_r = keyhole(head=9 mm, slot_width=4.5 mm, length=12 mm, cx=40, cy=plate_h / 2 - 40)
        hole dowel { c = Circle(center=(0, 40), diameter=12.5) }
        pocket_y = -plate_h / 2 + foot          # the pocket's underside, in this frame
        m_left = tab_and_slot(part="slot", length=H, thickness=T, tabs=2, tab=25 mm, screw=0,
                              rotation=90 deg, cx=-W / 2 + T / 2, cy=pocket_y + H / 2)
        m_right = tab_and_slot(part="slot", length=H, thickness=T, tabs=2, tab=25 mm, screw=0,
                               rotation=90 deg, cx=W / 2 - T / 2, cy=pocket_y + H / 2)
        m_bottom = tab_and_slot(part="slot", length=W, thickness=T, tabs=2, tab=30 mm, screw=0,
                                cx=0, cy=pocket_y + T / 2)
        Fixed(body)
    }
    solid front {
        p = finger_panel(width=W, height=H, thickness=T, finger=10 mm, bottom="fingers",
                         right="fingers", top="flat", left="fingers")
        drawing word {
            t = Text("SCOOP", position=(0, 22), size=20, font="sans:Bold", valign="middle",
                     fill=true)
        }
        drawing paw {
            pad = Ellipse(center=(0, -25), rx=11, ry=9, fill=true)
            toe1 = Circle(center=(-14, -10), radius=4, fill=true)
            toe2 = Circle(center=(-5, -4), radius=4, fill=true)
            toe3 = Circle(center=(5, -4), radius=4, fill=true)
            toe4 = Circle(center=(14, -10), radius=4, fill=true)
        }
    }
    side_l = side_panel()
    side_r = side_panel()
    solid bottom {
        p = finger_panel(width=W, height=D + T, thickness=T, finger=10 mm, bottom="flat",
                         right="slots", top="slots", left="slots")
        back = tab_and_slot(part="tab", length=W, thickness=T, tabs=2, tab=30 mm, screw=0,
                            rotation=180 deg, cx=0, cy=-(D + T) / 2)
        hole drain { c = Circle(center=(-40, -10), diameter=6) }
        drains = GridPattern(drain, 2, 5, (20, 20))
    }

    # flat on the sheet
    plate.body.center == (0, 0)
    RightOf(front, plate, gap=6)
    AlignTop(front, plate.body)
    Below(bottom, front, gap=6)
    AlignLeft(bottom, front)
    RightOf(side_l, front, gap=6)
    AlignTop(side_l, front)
    Below(side_r, side_l, gap=6)
    AlignLeft(side_r, side_l)

    # in 3D: x across, y out from the wall, z up from the pocket's underside
    Place(plate, rotation=(90 deg, 0, 0), position=(0, 0, plate_h / 2 - foot))
    Place(front, rotation=(90 deg, 0, 180 deg), position=(0, D - T, H / 2))
    Place(side_l, rotation=(90 deg, 0, 90 deg), position=(-W / 2, (D - T) / 2, H / 2))
    Place(side_r, rotation=(90 deg, 0, 90 deg), position=(W / 2 - T, (D - T) / 2, H / 2))
    Place(bottom, position=(0, (D - T) / 2, 0))

    assert plate.body.bb.width == 150 mm and plate.body.bb.height == 310 mm, "plate 150 x 310"
    assert plate.bb.top - plate.body.bb.top == 35 mm, "ears 35 mm above"
    assert distance(plate.hang_l.head_hole.center, plate.hang_r.head_hole.center) == 80 mm, "keyholes 80 apart"
    assert plate.body.bb.top - plate.hang_l.head_hole.center.y == 40 mm, "keyholes 40 below the top"
    assert plate.dowel.c.center.y - plate.body.center.y == 40 mm, "dowel 40 above the middle"
    assert front.p.outline.width == 130 mm and front.p.outline.height == 110 mm, "pocket 130 wide, 110 tall"
    assert side_l.p.outline.width - T == 60 mm, "60 deep from the wall"
    assert len(bottom.drains) == 10, "2 x 5 drain holes"
    assert plate.m_bottom.bb.bottom - plate.body.bb.bottom == 10 mm, "pocket 10 mm above the plate's foot"
}
