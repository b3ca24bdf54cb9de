# Request: a wall rack for the shower that keeps three bottles (shampoo, conditioner, body
# wash) upside down on their caps so the last drops run out. 5 mm clear acrylic. A back plate
# 260 wide x 200 tall, top corners r10, screwed to the wall with four countersunk M4 screws
# (two 15 mm below the top, 200 apart; two 20 mm above the bottom, 120 apart). A shelf
# 260 x 80 deep, its top 75 mm above the back's bottom, with three U notches 34 mm wide and
# 45 mm deep from its front edge, 85 mm apart, for the bottles' necks; notch mouths rounded r3.
# Two 60 x 60 triangular brackets under the shelf, 240 apart (centre to centre). All glued
# with tabs in slots (15 mm tabs on the brackets, three 30 mm tabs on the shelf). The bottle
# names engraved (filled) on the back under the shelf, under each notch, 6 mm tall.

import "std/joints.aidl"
import "std/fasteners.aidl"

thickness 5 mm

t = 5 mm
W = 260 mm
back_h = 200 mm
shelf_d = 80 mm
shelf_z = 70 mm      # underside of the shelf above the back's bottom
L = 60 mm            # bracket legs
bracket_x = 120 mm   # brackets' middles from the centre line
pitch = 85 mm
names = ["SHAMPOO", "CONDITIONER", "BODY WASH"]

def bracket() -> solid {
    # drawn with x = depth out from the back's face, y = height above the bracket's foot
    body = Polygon([(-t, 0), (-t, L), (0, L), (0, L + t), (L, L + t), (L, L - 5)])
    to_back = tab_and_slot(part="tab", length=L, thickness=t, tabs=2, tab=15 mm, screw=0,
                           rotation=90 deg, cx=-t, cy=L / 2)
    to_shelf = tab_and_slot(part="tab", length=L, thickness=t, tabs=2, tab=15 mm, screw=0,
                            rotation=0 deg, cx=L / 2, cy=L + t)
}

assembly shampoo_rack {
    solid back {
        # back's frame: y = z - back_h / 2
        body = RoundedRectangle(center=(0, 0), width=W, height=back_h,
                                corner_radii=[10, 10, 0, 0])
        top_l = clearance_hole(size=4, cx=-100, cy=back_h / 2 - 15)
        top_r = clearance_hole(size=4, cx=100, cy=back_h / 2 - 15)
        low_l = clearance_hole(size=4, cx=-60, cy=20 - back_h / 2)
        low_r = clearance_hole(size=4, cx=60, cy=20 - back_h / 2)
        Countersink([top_l, top_r, low_l, low_r], diameter=8.5)
        s_shelf = tab_and_slot(part="slot", length=W, thickness=t, tabs=3, tab=30 mm,
                               screw=0, rotation=0 deg, cx=0, cy=shelf_z + t / 2 - back_h / 2)
        s_left = tab_and_slot(part="slot", length=L, thickness=t, tabs=2, tab=15 mm, screw=0,
                              rotation=90 deg, cx=-bracket_x,
                              cy=shelf_z - L / 2 - back_h / 2)
        s_right = tab_and_slot(part="slot", length=L, thickness=t, tabs=2, tab=15 mm, screw=0,
                               rotation=90 deg, cx=bracket_x,
                               cy=shelf_z - L / 2 - back_h / 2)
        drawing labels {
            for i in range(3) {
                n = Text(names[i], position=((i - 1) * pitch, 45 - back_h / 2), size=6,
                         font="sans:Bold", valign="middle", fill=true, max_width=75)
            }
        }
        Fixed(body)
        assert body.width == 260 mm and body.height == 200 mm, "back 260 x 200"
        assert top_r.c.center.x - top_l.c.center.x == 200 mm, "top screws 200 apart"
        assert body.bb.top - top_l.c.center.y == 15 mm, "top screws 15 below the top"
        assert low_r.c.center.x - low_l.c.center.x == 120 mm, "low screws 120 apart"
        assert low_l.c.center.y - body.bb.bottom == 20 mm, "low screws 20 up"
        assert len(labels.n) == 3, "three labels"
    }

    solid shelf {
        # seen from above: y = 0 at the back's face, the room toward -y
        body = Rectangle(bottom_left=(-W / 2, -shelf_d), width=W, height=shelf_d + t)
        to_back = tab_and_slot(part="tab", length=W, thickness=t, tabs=3, tab=30 mm, screw=0,
                               rotation=0 deg, cx=0, cy=t)
        hole notch {
            for i in range(3) {
                s = Slot(start=((i - 1) * pitch, -shelf_d + 45 - 17),
                         end=((i - 1) * pitch, -shelf_d - 10), width=34)
            }
        }
        Fillet([[body.bottom, notch.s[0]], [body.bottom, notch.s[1]],
                [body.bottom, notch.s[2]]], 3)
        s_left = tab_and_slot(part="slot", length=L, thickness=t, tabs=2, tab=15 mm, screw=0,
                              rotation=90 deg, cx=-bracket_x, cy=-L / 2)
        s_right = tab_and_slot(part="slot", length=L, thickness=t, tabs=2, tab=15 mm, screw=0,
                               rotation=90 deg, cx=bracket_x, cy=-L / 2)
        Fixed(body)
        assert body.width == 260 mm and body.bb.top - t - body.bb.bottom == 80 mm, "shelf 260 x 80"
        assert notch.s[0].width == 34 mm, "notches 34 wide"
        assert -shelf_d + 45 mm == notch.s[0].start.y + notch.s[0].radius, "notches 45 deep"
        assert notch.s[1].start.x - notch.s[0].start.x == 85 mm, "notches 85 apart"
    }

    left = bracket()
    right = bracket()

    # flat on the sheet
    Below(shelf, back, gap=10)
    AlignLeft(shelf, back)
    RightOf(left, back, gap=10)
    AlignTop(left, back)
    Below(right, left, gap=10)
    AlignLeft(right, left)

    # in 3D: x across, y toward the wall (the room is -y), z up
    Place(back, position=(0, t, back_h / 2), rotation=(90 deg, 0, 0))
    Place(shelf, position=(0, 0, shelf_z))
    Place(left, position=(-bracket_x + t / 2, 0, shelf_z - L), rotation=(90 deg, 0, -90 deg))
    Place(right, position=(bracket_x + t / 2, 0, shelf_z - L), rotation=(90 deg, 0, -90 deg))

    assert shelf_z + t == 75 mm, "shelf top 75 up"
    assert 2 * bracket_x == 240 mm, "brackets 240 apart"
}
