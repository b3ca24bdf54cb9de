# Request (bathroom): a make-up organiser for the bathroom counter, 3 mm acrylic. An open
# finger-jointed tray 240 x 120 x 70 mm outside, split by two cross dividers into three equal
# compartments side by side (brushes, palettes, lipsticks). "MAKE-UP" engraved, filled bold
# letters 14 mm tall, centred on the front wall. In the right-hand compartment a lipstick
# stand: a 72 x 108 mm top plate with six 17 mm holes (3 rows front to back, 30 mm apart, by
# 2 columns 28 mm apart), held with its top face 39 mm above the tray's floor by two 100 mm
# long legs glued with two 20 mm tabs each into slots 3.5 mm in from the plate's side edges.

import "std/boxes.aidl"
import "std/joints.aidl"

thickness 3 mm

T = 3 mm
L = 240 mm
D = 120 mm
HT = 70 mm
COLS = 3
comp_w = (L - 2 * T - (COLS - 1) * T) / COLS
right_cx = L / 2 - T - comp_w / 2
TOP_W = 72 mm
TOP_D = 108 mm
LEG_H = 36 mm          # 33 mm of leg under the plate + 3 mm of tab through it
leg_x = TOP_W / 2 - 3.5 mm

assembly organizer {
    tray = divider_tray(length=L, width=D, height=HT, rows=1, cols=COLS, thickness=T,
                        finger=10 mm)

    drawing label {
        word = Text("MAKE-UP", position=(0, 0), size=14, valign="middle", font="sans:Bold",
                    fill=true)
    }
    CenterInside(label, tray.body.front)
    CutInto(label, tray.body.front)

    solid stand_top {
        plate = RoundedRectangle(center=(0, 0), width=TOP_W, height=TOP_D, corner_radius=4)
        hole lipstick {
            c = Circle(center=(-14, -30), diameter=17)
        }
        holes = GridPattern(lipstick, 3, 2, (28, 30))
        left_slots = tab_and_slot(part="slot", length=100 mm, thickness=T, tabs=2, tab=20 mm,
                                  screw=0, rotation=90 deg, cx=-leg_x, cy=0 mm)
        right_slots = tab_and_slot(part="slot", length=100 mm, thickness=T, tabs=2, tab=20 mm,
                                   screw=0, rotation=90 deg, cx=leg_x, cy=0 mm)
        Fixed(plate)
    }

    def leg() -> solid {
        side = Rectangle(center=(0, 0), width=100, height=LEG_H)
        tabs = tab_and_slot(part="tab", length=100 mm, thickness=T, tabs=2, tab=20 mm, screw=0,
                            cx=0 mm, cy=LEG_H / 2)
    }
    leg_a = leg()
    leg_b = leg()

    # flat on the sheet: the stand's parts to the right of the tray's net
    RightOf(stand_top, tray, gap=10)
    AlignTop(stand_top, tray)
    Below(leg_a, stand_top, gap=10)
    Below(leg_b, leg_a, gap=10)
    AlignLeft(leg_a, stand_top)
    AlignLeft(leg_b, stand_top)

    # in 3D: the stand in the right compartment, on the tray's floor (z = 3)
    Place(stand_top, position=(right_cx, 0, T + LEG_H - T), face="up", up="back")
    Place(leg_a, position=(right_cx - leg_x - T / 2, 0, T + LEG_H / 2), face="right", up="up")
    Place(leg_b, position=(right_cx + leg_x - T / 2, 0, T + LEG_H / 2), face="right", up="up")

    assert tray.length == 240 mm and tray.width == 120 mm and tray.height == 70 mm,
        "tray 240 x 120 x 70 outside"
    assert len(stand_top.holes) == 6, "six lipsticks"
    assert stand_top.holes[1].c.center.x - stand_top.holes[0].c.center.x == 28 mm, "columns 28 apart"
    assert stand_top.holes[2].c.center.y - stand_top.holes[0].c.center.y == 30 mm, "rows 30 apart"
    assert (T + LEG_H - T) + T - T == 39 mm - T, "top face 39 mm above the floor"
    assert TOP_W < comp_w, "the stand fits its compartment"
    assert stand_top.plate.bb.right - stand_top.right_slots.bb.right == 3.5 mm - T / 2,
        "legs 3.5 mm in from the plate's edges"
}
