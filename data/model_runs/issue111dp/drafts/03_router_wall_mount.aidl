# Request (electronics): a wall holder for a Wi-Fi router (220 x 40 x 150 mm) that stands on
# its long edge in a trough; 4 mm ply. Back plate 250 x 190 mm, R6 corners, hung on two
# screws by keyholes (9 mm head, 4.5 mm slot, 10 mm long, upward) 180 mm apart, 20 mm below
# the top edge; a honeycomb of hexagonal vents 10 mm across flats (7 staggered rows of 13,
# 16 mm apart in a row, rows 14 mm apart) behind the router. The trough is an open box
# without back, finger-jointed (8 mm fingers): floor 234 x 48 mm, front lip 234 x 30 mm,
# two end cheeks 48 x 30 mm, so the router has 3 mm clearance each end and 4 mm front to
# back; its floor's underside is 10 mm above the back plate's bottom edge. The floor is
# glued into the back plate by three 25 mm tabs, each cheek by one 15 mm tab. A 40 x 14 mm
# cable slot in the floor, centred 30 mm from the right end. "HOMENET-5G" engraved filled
# (10 mm, bold) on the front of the lip.

import "std/joints.aidl"
import "std/plates.aidl"

thickness 4 mm

t = 4 mm
back_w = 250 mm
back_h = 190 mm
trough_l = 234 mm
trough_d = 48 mm
trough_h = 30 mm
floor_z = -back_h / 2 + 10 mm           # underside of the floor, on the back plate
cheek_x = trough_l / 2 - t / 2          # cheek's middle plane

def cheek() -> solid {
    # x: front (-) to back (+), y: up; tab strip on the back edge
    p = finger_panel(width=trough_d, height=trough_h, thickness=t, finger=8 mm,
                     bottom="slots", left="slots", right="flat", top="flat")
    strip = Rectangle(center=(trough_d / 2 + t / 2, 0), width=t, height=trough_h)
    tab = tab_and_slot(part="tab", length=trough_h, thickness=t, tabs=1, tab=15 mm, screw=0,
                       rotation=-90 deg, cx=trough_d / 2 + t, cy=0)
    Fixed(p)
    Fixed(strip)
}

assembly router_mount {
    solid back {
        plate = RoundedRectangle(center=(0, 0), width=back_w, height=back_h, corner_radius=6)
        k1 = keyhole(head=9 mm, slot_width=4.5 mm, length=10 mm, cx=-90 mm, cy=back_h / 2 - 20 mm)
        k2 = keyhole(head=9 mm, slot_width=4.5 mm, length=10 mm, cx=90 mm, cy=back_h / 2 - 20 mm)
        # FIX after the first valid program: the honeycomb was 4 mm right of centre (first
        # vent at x -96; 12 steps of 16 plus the 8 mm stagger span 200 mm: start at -100)
        hole vent { hx = RegularPolygon(center=(-(12 * 16 mm + 8 mm) / 2, -40), across_flats=10,
                                        sides=6) }
        vents = GridPattern(vent, 7, 13, col_spacing=16 mm, row_spacing=14 mm, stagger=true)
        mf = tab_and_slot(part="slot", length=trough_l, thickness=t, tabs=3, tab=25 mm,
                          screw=0, cx=0, cy=floor_z + t / 2)
        ml = tab_and_slot(part="slot", length=trough_h, thickness=t, tabs=1, tab=15 mm,
                          screw=0, rotation=90 deg, cx=-cheek_x, cy=floor_z + trough_h / 2)
        mr = tab_and_slot(part="slot", length=trough_h, thickness=t, tabs=1, tab=15 mm,
                          screw=0, rotation=90 deg, cx=cheek_x, cy=floor_z + trough_h / 2)
        Fixed(plate)
        Fixed(vent)
        assert len(vents) == 91
        assert abs((vents[0].bb.left + vents[25].bb.right) / 2 - plate.bb.center_x) < 0.01 mm,
            "honeycomb centred"
        assert k2.head_hole.center.x - k1.head_hole.center.x == 180 mm
        assert plate.bb.top - k1.head_hole.center.y == 20 mm
        assert mf.slot[0].bb.bottom - plate.bb.bottom == 10 mm, "floor 10 mm above the bottom"
    }

    solid floor {
        p = finger_panel(width=trough_l, height=trough_d, thickness=t, finger=8 mm,
                         bottom="fingers", left="fingers", right="fingers", top="flat")
        strip = Rectangle(center=(0, trough_d / 2 + t / 2), width=trough_l, height=t)
        tabs = tab_and_slot(part="tab", length=trough_l, thickness=t, tabs=3, tab=25 mm,
                            screw=0, cx=0, cy=trough_d / 2 + t)
        hole cable { s = Slot(center=(trough_l / 2 - 30 mm, 8), length=40, width=14) }
        Fixed(p)
        Fixed(strip)
        Fixed(cable)
        assert p.outline.bb.right - cable.s.center.x == 30 mm
        assert trough_l - 2 * t - 220 mm == 6 mm, "3 mm clearance each end"
        assert trough_d - t - 40 mm == 4 mm, "4 mm front to back"
    }

    solid lip {
        p = finger_panel(width=trough_l, height=trough_h, thickness=t, finger=8 mm,
                         bottom="slots", left="fingers", right="fingers", top="flat")
        drawing name {
            n = Text("HOMENET-5G", position=(0, t / 2), size=10, font="sans:Bold",
                     valign="middle", fill=true)
        }
        Fixed(p)
    }

    left = cheek()
    right = cheek()

    # flat on the sheet
    Below(floor, back, gap=6)
    AlignLeft(floor, back)
    Below(lip, floor, gap=6)
    AlignLeft(lip, back)
    RightOf(left, back, gap=6)
    AlignTop(left, back)
    Below(right, left, gap=6)
    AlignLeft(right, left)

    # assembled: back plate on the wall (y = 0 its back face), the trough in front of it
    Place(back, position=(0, 0, 0), face="front", up="up")
    Place(floor, position=(0, -trough_d / 2 - t, floor_z), face="up", up="back")
    Place(lip, position=(0, -t - trough_d + t, floor_z + trough_h / 2), face="front", up="up")
    Place(left, position=(-trough_l / 2, -trough_d / 2 - t, floor_z + trough_h / 2),
          face="right", up="up")
    Place(right, position=(trough_l / 2 - t, -trough_d / 2 - t, floor_z + trough_h / 2),
          face="right", up="up")
}
