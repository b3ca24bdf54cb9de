# Request: a wall-hung mail holder for the hallway, cut from 4 mm birch ply. A back board
# 220 wide x 260 tall with its top corners rounded r10, hung on two wall screws through
# keyholes 160 mm apart, 25 mm below the top. Along the bottom of the back, four 2.5 mm pilot
# holes for brass cup hooks (keys), 45 mm apart, 18 mm up from the bottom edge. A pocket for
# letters 40 mm deep (inside) in front: a front board 220 wide x 130 tall whose bottom is
# 30 mm up from the back's bottom, with a 50 mm wide half-round finger dip in its top edge
# and the word MAIL cut right through in bold letters 40 mm tall; two sides 120 tall and a
# bottom, all glued with tabs in slots (tabs 20 mm on the sides, three 30 mm on the bottom).

import "std/joints.aidl"
import "std/plates.aidl"

thickness 4 mm

t = 4 mm          # ply
depth = 40 mm     # inside depth of the pocket
inner_w = 200 mm  # between the sides
side_h = 120 mm
bottom_z = 40 mm  # underside of the pocket's bottom, above the back's bottom edge
front_z = 30 mm   # the front's bottom edge above the back's bottom edge
front_h = 130 mm
back_h = 260 mm

def side_panel() -> solid {
    # drawn with x = depth (0 at the back's face), y = height above the pocket floor's underside
    body = Rectangle(bottom_left=(-t, 0), width=depth + 2 * t, height=side_h)
    to_back = tab_and_slot(part="tab", length=side_h, thickness=t, tabs=2, tab=20 mm,
                           screw=0, rotation=90 deg, cx=-t, cy=side_h / 2)
    to_front = tab_and_slot(part="tab", length=side_h, thickness=t, tabs=2, tab=20 mm,
                            screw=0, rotation=-90 deg, cx=depth + t, cy=side_h / 2)
}

assembly mail_holder {
    solid back {
        body = RoundedRectangle(center=(0, 0), width=220, height=back_h,
                                corner_radii=[10, 10, 0, 0])
        hang_l = keyhole(head=9 mm, slot_width=4.5 mm, length=10 mm, direction=90 deg,
                         cx=-80, cy=back_h / 2 - 25)
        hang_r = keyhole(head=9 mm, slot_width=4.5 mm, length=10 mm, direction=90 deg,
                         cx=80, cy=back_h / 2 - 25)
        hole hooks {
            for i in range(4) {
                c = Circle(center=(-67.5 + i * 45, -back_h / 2 + 18), diameter=2.5)
            }
        }
        # slots for the sides and the bottom (back's frame: y = z - back_h / 2)
        s_left = tab_and_slot(part="slot", length=side_h, thickness=t, tabs=2, tab=20 mm,
                              screw=0, rotation=90 deg, cx=-(inner_w / 2 + t / 2),
                              cy=bottom_z + side_h / 2 - back_h / 2)
        s_right = tab_and_slot(part="slot", length=side_h, thickness=t, tabs=2, tab=20 mm,
                               screw=0, rotation=90 deg, cx=inner_w / 2 + t / 2,
                               cy=bottom_z + side_h / 2 - back_h / 2)
        s_bottom = tab_and_slot(part="slot", length=inner_w, thickness=t, tabs=3, tab=30 mm,
                                screw=0, rotation=0 deg, cx=0,
                                cy=bottom_z + t / 2 - back_h / 2)
        Fixed(body)
        assert hang_r.head_hole.center.x - hang_l.head_hole.center.x == 160 mm, "keyholes 160 apart"
        assert body.bb.top - hang_l.head_hole.center.y == 25 mm, "keyholes 25 below the top"
        assert len(hooks.c) == 4, "four cup hooks"
        assert hooks.c[1].center.x - hooks.c[0].center.x == 45 mm, "hooks 45 apart"
        assert hooks.c[0].center.y - body.bb.bottom == 18 mm, "hooks 18 up"
        assert body.width == 220 mm and body.height == 260 mm, "back 220 x 260"
    }

    solid front {
        # front's frame: y = z - (front_z + front_h / 2)
        body = Rectangle(center=(0, 0), width=220, height=front_h)
        hole dip {
            c = Circle(center=(0, front_h / 2), diameter=50)
        }
        hole word {
            w = Text("MAIL", position=(0, -5), size=40, font="sans:Bold", valign="middle",
                     stencil=true)
        }
        s_left = tab_and_slot(part="slot", length=side_h, thickness=t, tabs=2, tab=20 mm,
                              screw=0, rotation=90 deg, cx=-(inner_w / 2 + t / 2),
                              cy=bottom_z + side_h / 2 - (front_z + front_h / 2))
        s_right = tab_and_slot(part="slot", length=side_h, thickness=t, tabs=2, tab=20 mm,
                               screw=0, rotation=90 deg, cx=inner_w / 2 + t / 2,
                               cy=bottom_z + side_h / 2 - (front_z + front_h / 2))
        s_bottom = tab_and_slot(part="slot", length=inner_w, thickness=t, tabs=3, tab=30 mm,
                                screw=0, rotation=0 deg, cx=0,
                                cy=bottom_z + t / 2 - (front_z + front_h / 2))
        Fixed(body)
        assert body.height == 130 mm, "front 130 tall"
        assert word.w.size == 40 mm, "MAIL 40 mm tall"
    }

    solid bottom {
        # drawn as seen from above: y = 0 at the back's face, the room toward -y
        body = Rectangle(bottom_left=(-inner_w / 2, -depth - t), width=inner_w,
                         height=depth + 2 * t)
        to_back = tab_and_slot(part="tab", length=inner_w, thickness=t, tabs=3, tab=30 mm,
                               screw=0, rotation=0 deg, cx=0, cy=t)
        to_front = tab_and_slot(part="tab", length=inner_w, thickness=t, tabs=3, tab=30 mm,
                                screw=0, rotation=180 deg, cx=0, cy=-depth - t)
    }

    left = side_panel()
    right = side_panel()

    # flat on the sheet
    RightOf(front, back, gap=10)
    AlignTop(front, back)
    Below(bottom, front, gap=10)
    AlignLeft(bottom, front)
    Below(left, bottom, gap=10)
    AlignLeft(left, bottom)
    RightOf(right, left, gap=10)
    AlignTop(right, left)

    # in 3D: x across, y toward the wall (the room is -y), z up
    Place(back, position=(0, t, back_h / 2), rotation=(90 deg, 0, 0))
    Place(front, position=(0, -depth, front_z + front_h / 2), rotation=(90 deg, 0, 0))
    Place(bottom, position=(0, 0, bottom_z))
    Place(left, position=(-inner_w / 2, 0, bottom_z), rotation=(90 deg, 0, -90 deg))
    Place(right, position=(inner_w / 2 + t, 0, bottom_z), rotation=(90 deg, 0, -90 deg))

    assert front_z - 0 == 30 mm and depth == 40 mm, "pocket 40 deep, front 30 up"
}
