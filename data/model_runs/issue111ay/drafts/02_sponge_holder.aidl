# Request (kitchen): a sponge caddy that sticks inside the sink on two suction cups, from 3 mm
# clear acrylic. Base 120 x 70 mm with five drain slots 6 mm wide and 40 mm long, running
# front to back, 18 mm apart, centred. A front lip 120 x 30 mm whose top edge dips in a
# shallow curve 80 mm wide and 10 mm deep in the middle (to grab the sponge), with "SPONGE"
# engraved 5 mm tall under the dip. A back 120 x 90 mm with rounded top corners (10 mm) and
# two keyholes for the suction cups (12 mm head, 6 mm neck slot 10 mm long, upward), 60 mm
# apart, their heads 20 mm below the top. Front and back are glued into the base with two
# 15 mm tabs each; each wall stands 5 mm in from the base's front or back edge.

units mm
thickness 3 mm

import "std/joints.aidl"
import "std/plates.aidl"

param width = 120 mm, min = 80 mm, max = 200 mm
param depth = 70 mm, min = 50 mm, max = 120 mm
param lip_h = 30 mm, min = 20 mm, max = 50 mm
param back_h = 90 mm, min = 60 mm, max = 150 mm

t = 3 mm
inset = 5 mm                 # material in front of each wall's slots
wall_y = depth / 2 - inset - t / 2   # the walls' middles from the base's centre

assembly caddy {
    solid base {
        body = Rectangle(center=(0, 0), width=width, height=depth)
        hole drain {
            s = Slot(center=(-36, 0), length=40, width=6, rotation=90 deg)
        }
        drains = LinearPattern(drain, 5, (18, 0))
        front_slots = tab_and_slot(part="slot", length=width, thickness=t, tabs=2, tab=15 mm,
                                   screw=0, cx=0 mm, cy=-wall_y)
        back_slots = tab_and_slot(part="slot", length=width, thickness=t, tabs=2, tab=15 mm,
                                  screw=0, cx=0 mm, cy=wall_y)
        Fixed(body)
        assert len(drains) == 5
        assert drains[1].s.center.x - drains[0].s.center.x == 18 mm
        assert drains[0].s.length == 40 mm and drains[0].s.width == 6 mm
        assert abs((drains[0].s.center.x + drains[4].s.center.x) / 2 - body.center.x) < 0.001 mm,
            "drains centred"
        assert front_slots.bb.bottom - body.bb.bottom == inset, "front wall 5 mm in"
        assert body.bb.top - back_slots.bb.top == inset, "back wall 5 mm in"
    }

    solid front {
        body = Rectangle(bottom_left=(-width / 2, 0), width=width, height=lip_h)
        hole dip {
            # a circle through the dip's two ends on the top edge and 10 mm below it
            c = Circle(center=(0, lip_h - 10 + 85), radius=85)
        }
        tabs = tab_and_slot(part="tab", length=width, thickness=t, tabs=2, tab=15 mm, screw=0,
                            rotation=180 deg, cx=0 mm, cy=0 mm)
        drawing label {
            w = Text("SPONGE", position=(0, 10), size=5, valign="middle")
        }
        Fixed(body)
        assert body.bb.top - dip.c.bottom.y == 10 mm, "dip 10 mm deep"
        assert body.bb.width == 120 mm and body.bb.height == 30 mm
        assert label.bb.top < dip.c.bottom.y - 2 mm, "label under the dip"
    }

    solid back {
        body = RoundedRectangle(bottom_left=(-width / 2, 0), width=width, height=back_h,
                                corner_radii=[10, 10, 0, 0])
        left_cup = keyhole(head=12 mm, slot_width=6 mm, length=10 mm, direction=90 deg,
                           cx=-30 mm, cy=back_h - 20 mm)
        right_cup = keyhole(head=12 mm, slot_width=6 mm, length=10 mm, direction=90 deg,
                            cx=30 mm, cy=back_h - 20 mm)
        tabs = tab_and_slot(part="tab", length=width, thickness=t, tabs=2, tab=15 mm, screw=0,
                            rotation=180 deg, cx=0 mm, cy=0 mm)
        Fixed(body)
        Fixed(left_cup)
        Fixed(right_cup)
        assert right_cup.head_hole.center.x - left_cup.head_hole.center.x == 60 mm
        assert body.bb.top - left_cup.head_hole.center.y == 20 mm
        assert body.bb.height == 90 mm
    }

    # flat for cutting
    Above(front, base, gap=6)
    Above(back, front, gap=6)
    AlignCenterX(front, base)
    AlignCenterX(back, base)

    # assembled: walls stood on the base, tabs through its slots
    Place(front, position=(0, -wall_y + t / 2, 0), rotation=(90 deg, 0, 0))
    Place(back, position=(0, wall_y + t / 2, 0), rotation=(90 deg, 0, 0))
}
