# Request (kitchen): a wall-mounted holder for size-4 cone coffee filters, 3 mm ply, glued.
# A pocket 220 mm wide and 25 mm deep inside, 90 mm tall at its sides.
# - back: 250 x 160, two keyholes (8 mm head, 4 mm slot 10 mm long, pointing up), their
#   heads 40 mm in from the side edges and 20 mm below the top edge;
# - front: 240 x 100, a 60 mm diameter thumb notch centred on its top edge, "COFFEE FILTERS"
#   engraved 8 mm tall, centred left-right, its middle 12 mm below the plate's centre;
# - the pocket's floor 10 mm above the bottom edges of back and front;
# - two sides 90 tall, each with 2 tabs 20 mm wide on its back and front edges into slots;
# - a bottom panel between the sides, 3 tabs 30 mm wide on its back and front edges.

import "std/joints.aidl"
import "std/plates.aidl"

units mm
thickness 3 mm

T = 3 mm
inner_w = 220 mm
inner_d = 25 mm
side_h = 90 mm
back_w = 250 mm
back_h = 160 mm
front_w = 240 mm
front_h = 100 mm
floor_up = 10 mm

# slot lines for the sides, measured from a panel's centre
side_x = inner_w / 2 + T / 2

assembly filter_holder {
    solid back {
        body = Rectangle(center=(0, 0), width=back_w, height=back_h)
        Fixed(body)
        hang_l = keyhole(head=8 mm, slot_width=4 mm, length=10 mm, direction=90 deg,
                         cx=-back_w / 2 + 40 mm, cy=back_h / 2 - 20 mm)
        hang_r = keyhole(head=8 mm, slot_width=4 mm, length=10 mm, direction=90 deg,
                         cx=back_w / 2 - 40 mm, cy=back_h / 2 - 20 mm)
        sl = tab_and_slot(part="slot", length=side_h, thickness=T, tabs=2, tab=20 mm, screw=0,
                          rotation=90 deg, cx=-side_x, cy=-back_h / 2 + floor_up + side_h / 2)
        sr = tab_and_slot(part="slot", length=side_h, thickness=T, tabs=2, tab=20 mm, screw=0,
                          rotation=90 deg, cx=side_x, cy=-back_h / 2 + floor_up + side_h / 2)
        sb = tab_and_slot(part="slot", length=inner_w, thickness=T, tabs=3, tab=30 mm, screw=0,
                          rotation=0 deg, cx=0, cy=-back_h / 2 + floor_up + T / 2)
    }

    solid front {
        body = Rectangle(center=(0, 0), width=front_w, height=front_h)
        Fixed(body)
        hole thumb {
            c = Circle(center=(0, front_h / 2), diameter=60 mm)
        }
        sl = tab_and_slot(part="slot", length=side_h, thickness=T, tabs=2, tab=20 mm, screw=0,
                          rotation=90 deg, cx=-side_x, cy=-front_h / 2 + floor_up + side_h / 2)
        sr = tab_and_slot(part="slot", length=side_h, thickness=T, tabs=2, tab=20 mm, screw=0,
                          rotation=90 deg, cx=side_x, cy=-front_h / 2 + floor_up + side_h / 2)
        sb = tab_and_slot(part="slot", length=inner_w, thickness=T, tabs=3, tab=30 mm, screw=0,
                          rotation=0 deg, cx=0, cy=-front_h / 2 + floor_up + T / 2)
        drawing label {
            t = Text("COFFEE FILTERS", position=(0, -12), size=8, valign="middle")
        }
    }

    def side_panel() -> solid {
        body = Rectangle(center=(0, 0), width=inner_d + 2 * T, height=side_h)
        Fixed(body)
        to_back = tab_and_slot(part="tab", length=side_h, thickness=T, tabs=2, tab=20 mm,
                               screw=0, rotation=90 deg, cx=-(inner_d / 2 + T), cy=0)
        to_front = tab_and_slot(part="tab", length=side_h, thickness=T, tabs=2, tab=20 mm,
                                screw=0, rotation=-90 deg, cx=inner_d / 2 + T, cy=0)
    }

    left = side_panel()
    right = side_panel()

    solid floor {
        body = Rectangle(center=(0, 0), width=inner_w, height=inner_d + 2 * T)
        Fixed(body)
        to_back = tab_and_slot(part="tab", length=inner_w, thickness=T, tabs=3, tab=30 mm,
                               screw=0, rotation=0 deg, cx=0, cy=inner_d / 2 + T)
        to_front = tab_and_slot(part="tab", length=inner_w, thickness=T, tabs=3, tab=30 mm,
                                screw=0, rotation=180 deg, cx=0, cy=-(inner_d / 2 + T))
    }

    # laid out flat, apart
    Fixed(back)
    RightOf(front, back, gap=10)
    AlignTop(front, back)
    Below(floor, front, gap=10)
    AlignLeft(floor, front)
    RightOf(left, back, gap=10)
    Below(left, floor, gap=10)
    RightOf(right, left, gap=10)
    AlignBottom(right, left)

    assert back.body.bb.width == 250 mm and back.body.bb.height == 160 mm, "back 250 x 160"
    assert front.body.bb.width == 240 mm and front.body.bb.height == 100 mm, "front 240 x 100"
    assert front.thumb.c.diameter == 60 mm, "60 mm thumb notch"
    assert abs(back.hang_l.head_hole.center.x - back.body.bb.left - 40 mm) < 0.01 mm, "keyhole 40 in"
    assert abs(back.body.bb.top - back.hang_r.head_hole.center.y - 20 mm) < 0.01 mm, "keyhole 20 down"
    assert left.body.bb.height == 90 mm, "sides 90 tall"
    assert left.body.bb.width - 2 * T == 25 mm, "pocket 25 deep inside"
    assert floor.body.bb.width == 220 mm, "pocket 220 wide inside"
    assert abs(front.label.t.position.y - front.body.center.y + 12 mm) < 0.01 mm, "label 12 below centre"
}
