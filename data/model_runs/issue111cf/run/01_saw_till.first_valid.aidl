# Request: a wall-hung saw till for four hand saws (rip, crosscut, tenon, dovetail), 6 mm
# birch ply. A 400 x 240 mm back plate with 8 mm corners, hung on two screws by keyholes
# 320 mm apart near the top, "HAND SAWS" engraved on it. A 380 mm rail stands out 60 mm
# from the back with four open slots 3 mm wide and 40 mm deep, 85 mm apart, from its front
# edge (the blades drop in, the handles rest on the rail); each saw's name engraved behind
# its slot. The rail is glued into the back by three 40 mm tabs through mortises; two
# triangular brackets (80 mm high, 55 mm deep) under the rail's ends, each glued into the
# back and up into the rail by two tabs.

import "std/joints.aidl"
import "std/plates.aidl"

thickness 6 mm

T = 6 mm
names = ["RIP", "XCUT", "TENON", "DOVE"]

# a triangular bracket: back edge (x = 0) against the back plate, top edge (y = 0) under
# the rail; tabs stand 6 mm past both edges
def bracket() -> solid {
    web = Polygon([(0, 0), (55, 0), (0, -80)])
    top_strip = Rectangle(bottom_left=(0, 0), width=55, height=6)
    back_strip = Rectangle(bottom_left=(-6, -80), width=6, height=80)
    up = tab_and_slot(part="tab", length=55 mm, thickness=6 mm, tabs=2, tab=15 mm, screw=0,
                      cx=27.5 mm, cy=6 mm)
    into_back = tab_and_slot(part="tab", length=80 mm, thickness=6 mm, tabs=2, tab=20 mm,
                             screw=0, rotation=90 deg, cx=-6 mm, cy=-40 mm)
}

assembly saw_till {
    solid back {
        body = RoundedRectangle(center=(0, 0), width=400, height=240, corner_radius=8)
        hang_l = keyhole(cx=-160 mm, cy=90 mm)
        hang_r = keyhole(cx=160 mm, cy=90 mm)
        rail_mortise = tab_and_slot(part="slot", length=380 mm, thickness=6 mm, tabs=3,
                                    tab=40 mm, screw=0, cx=0 mm, cy=-20 mm)
        left_mortise = tab_and_slot(part="slot", length=80 mm, thickness=6 mm, tabs=2,
                                    tab=20 mm, screw=0, rotation=90 deg, cx=-170 mm, cy=-63 mm)
        right_mortise = tab_and_slot(part="slot", length=80 mm, thickness=6 mm, tabs=2,
                                     tab=20 mm, screw=0, rotation=90 deg, cx=170 mm, cy=-63 mm)
        drawing title {
            t = Text("HAND SAWS", (0, 40), size=16)
        }
    }

    solid rail {
        # 60 mm standing out, plus the 6 mm of tabs through the back
        body = Rectangle(center=(0, -27), width=380, height=66)
        into_back = tab_and_slot(part="tab", length=380 mm, thickness=6 mm, tabs=3, tab=40 mm,
                                 screw=0, cx=0 mm, cy=6 mm)
        hole saw_slot {
            s = Rectangle(center=(-127.5, -41), width=3, height=42)
        }
        slots = LinearPattern(saw_slot, 4, (85 mm, 0))
        left_slot = tab_and_slot(part="slot", length=55 mm, thickness=6 mm, tabs=2, tab=15 mm,
                                 screw=0, rotation=90 deg, cx=-170 mm, cy=-27.5 mm)
        right_slot = tab_and_slot(part="slot", length=55 mm, thickness=6 mm, tabs=2, tab=15 mm,
                                  screw=0, rotation=90 deg, cx=170 mm, cy=-27.5 mm)
        drawing labels {
            for i in range(4) {
                t = Text(names[i], (-127.5 + i * 85, -15), size=5)
            }
        }
    }

    bl = bracket()
    br = bracket()

    # flat on the sheet: rail under the back, brackets under the rail
    Below(rail, back, gap=10)
    AlignCenterX(rail, back)
    Below(bl, rail, gap=10)
    Below(br, rail, gap=10)
    AlignLeft(bl, rail)
    AlignRight(br, rail)

    # in 3D: the back stands on the wall (its face at y = 0), the rail and brackets stick
    # out toward -y
    Place(back, position=(0, 6, 0), rotation=(90 deg, 0, 0))
    Place(rail, position=(0, 0, -23))
    Place(bl, position=(-167, 0, -23), rotation=(90 deg, 0, -90 deg))
    Place(br, position=(173, 0, -23), rotation=(90 deg, 0, -90 deg))

    assert back.body.bb.width == 400 mm and back.body.bb.height == 240 mm, "back 400 x 240"
    assert back.hang_r.head_hole.center.x - back.hang_l.head_hole.center.x == 320 mm,
        "keyholes 320 apart"
    assert len(rail.slots) == 4, "four saws"
    assert rail.slots[1].s.center.x - rail.slots[0].s.center.x == 85 mm, "slots 85 apart"
    assert rail.slots[0].s.bb.top - rail.body.bb.bottom == 40 mm, "slots 40 deep"
    assert rail.body.bb.height - T == 60 mm, "rail stands out 60"
    assert bl.web.bb.height == 80 mm and bl.web.bb.width == 55 mm, "brackets 80 x 55"
}
