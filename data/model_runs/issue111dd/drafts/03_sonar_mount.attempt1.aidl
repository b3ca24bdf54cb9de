# Request (electronics): a mount for an HC-SR04 ultrasonic sensor on my robot chassis, 3 mm acrylic,
# solvent-welded. Front plate 60 mm wide, 37 mm tall over all (tabs included), standing on a foot
# plate 60 x 52 mm: two 16.5 mm holes for the transducers (16 mm cans, centres 26 mm apart), the
# board's four M2 holes (42 x 17 mm pattern) as M2 clearance holes, the board's centre 21 mm above
# the foot, and a 9 x 4 mm relief for the crystal between the cans, its centre 7 mm above theirs.
# The plate's bottom edge has two 12 mm tabs into the foot; two triangular gussets 30 x 30 behind it,
# 26.5 mm each side of the centre, with one 10 mm tab into the plate and one into the foot. The
# foot has two M3 slots 12 mm long (fore and aft, 24 mm apart) for the chassis, and "HC-SR04"
# engraved on its 10.5 mm front lip.

import "std/joints.aidl"
import "std/fasteners.aidl"
import "std/shapes.aidl"

thickness 3 mm

board_y = 4 mm        # the board's centre in the plate's drawing (plate bottom tips at -20)

def gusset() -> solid {
    tri = Polygon([(0, 0), (30, 0), (0, 30)])
    hole corner { r = Rectangle(center=(1.5, 1.5), width=5, height=5) }
    foot_tab = tab_and_slot(part="tab", length=25 mm, thickness=3 mm, tabs=1, tab=10 mm, screw=0,
                            rotation=180 deg, cx=15.5 mm, cy=0 mm)
    plate_tab = tab_and_slot(part="tab", length=25 mm, thickness=3 mm, tabs=1, tab=10 mm, screw=0,
                             rotation=90 deg, cx=0 mm, cy=15.5 mm)
}

assembly sonar_mount {
    solid plate {
        body = Rectangle(center=(0, 0), width=60, height=40)
        foot_tabs = tab_and_slot(part="tab", length=60 mm, thickness=3 mm, tabs=2, tab=12 mm,
                                 screw=0, rotation=180 deg, cx=0 mm, cy=-20 mm)
        for s in [-1, 1] {
            hole can { c = Circle(center=(s * 13, board_y), diameter=16.5) }
            hole gusset_mortise_hole { r = Rectangle(center=(s * 26.5, -4.5), width=3, height=10) }
        }
        for p in [(-21, board_y - 8.5), (21, board_y - 8.5), (-21, board_y + 8.5), (21, board_y + 8.5)] {
            m2 = clearance_hole(size=2, cx=p[0], cy=p[1])
        }
        hole crystal { s = Slot(center=(0, board_y + 7), length=9, width=4) }
    }

    solid foot {
        body = Rectangle(center=(0, 14), width=60, height=52)
        plate_mortise = tab_and_slot(part="slot", length=60 mm, thickness=3 mm, tabs=2, tab=12 mm,
                                     screw=0, cx=0 mm, cy=0 mm)
        left_mortise = tab_and_slot(part="slot", length=25 mm, thickness=3 mm, tabs=1, tab=10 mm,
                                    screw=0, rotation=90 deg, cx=-26.5 mm, cy=14 mm)
        right_mortise = tab_and_slot(part="slot", length=25 mm, thickness=3 mm, tabs=1, tab=10 mm,
                                     screw=0, rotation=90 deg, cx=26.5 mm, cy=14 mm)
        left_slot = slot_hole(length=12 mm, width=3.4 mm, rotation=90 deg, cx=-12 mm, cy=27 mm)
        right_slot = slot_hole(length=12 mm, width=3.4 mm, rotation=90 deg, cx=12 mm, cy=27 mm)
        drawing label {
            t = Text("HC-SR04", position=(0, -6.75), size=4, valign="middle")
        }
    }

    g_left = gusset()
    g_right = gusset()

    # on the sheet
    RightOf(foot, plate, gap=6)
    AlignTop(foot, plate)
    Below(g_left, plate, gap=6)
    AlignLeft(g_left, plate)
    RightOf(g_right, g_left, gap=6)
    AlignTop(g_right, g_left)

    # assembled: plate's mid plane at y 0 (front face -1.5), foot flat under it
    Place(foot, position=(0, 0, 0))
    Place(plate, position=(0, 1.5 mm, 20 mm), face="front", up="up")
    Place(g_right, position=(25 mm, -1.5 mm, 0), face="right", up="up")
    Place(g_left, position=(-28 mm, -1.5 mm, 0), face="right", up="up")

    # the request's numbers
    assert plate.body.bb.width == 60 mm and plate.body.bb.height == 37 mm, "plate 60 wide, 37 tall"
    assert foot.body.bb.width == 60 mm and foot.body.bb.height == 52 mm, "foot 60 x 52"
    assert plate.can[0].c.diameter == 16.5 mm, "16.5 mm can holes"
    assert plate.can[1].c.center.x - plate.can[0].c.center.x == 26 mm, "cans 26 apart"
    assert plate.m2[1].c.center.x - plate.m2[0].c.center.x == 42 mm, "M2 pattern 42 wide"
    assert plate.m2[2].c.center.y - plate.m2[0].c.center.y == 17 mm, "M2 pattern 17 tall"
    assert plate.can[0].c.center.y - (plate.body.bb.bottom + 3 mm) == 21 mm, "board centre 21 above the foot"
    assert plate.crystal.s.center.y - plate.can[0].c.center.y == 7 mm, "crystal relief 7 above the cans"
    assert plate.can[1].c.center.x - plate.can[1].c.radius - plate.crystal.s.bb.right >= 1 mm, "relief clear of the cans"
    assert foot.right_slot.s.center.x - foot.left_slot.s.center.x == 24 mm, "M3 slots 24 apart"
    assert foot.right_slot.s.length == 12 mm, "slots 12 long"
    assert g_left.tri.bb.width == 30 mm and g_left.tri.bb.height == 30 mm, "gussets 30 x 30"
    assert foot.plate_mortise.slot[0].bb.bottom - foot.body.bb.bottom == 10.5 mm, "10.5 mm front lip"
}
