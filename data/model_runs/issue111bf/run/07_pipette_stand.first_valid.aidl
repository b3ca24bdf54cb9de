# Request (science): a linear stand for six micropipettes on the lab bench, 6 mm ply, 4 parts.
# Two side panels 320 mm tall, 120 mm deep at the foot and 70 mm at the top (top corners r10,
# a 30 mm wide slotted window to save weight); a hanger shelf 240 mm between the sides and 70 mm
# deep whose mid-plane is 300 mm up, with six notches 16 mm wide and 35 mm deep from the front edge
# (round ends), 38 mm apart, and "PIPETTES" engraved behind them; a drip tray 240 x 110 mm whose
# mid-plane is 18 mm up, engraved under each notch: P2, P10, P20, P200, P1000, P5000. Shelf and tray
# end in one through-tenon each side (30 mm and 40 mm wide) in mortises with 0.1 mm clearance.

import "std/joints.aidl"

units mm
thickness 6 mm

ply = 6 mm
inner = 240 mm            # between the sides
shelf_d = 70 mm
tray_d = 110 mm
shelf_z = 300 mm          # mid-plane heights
tray_z = 18 mm
pitch = 38 mm
names = ["P2", "P10", "P20", "P200", "P1000", "P5000"]

def side() -> solid {
    frame = Trapezoid(center=(0, 160), bottom_width=120, top_width=70, height=320)
    shelf_mortise = tab_and_slot(part="slot", length=70 mm, thickness=6 mm, tabs=1, tab=30 mm,
                                 screw=0, clearance=0.1 mm, cx=0 mm, cy=shelf_z)
    tray_mortise = tab_and_slot(part="slot", length=110 mm, thickness=6 mm, tabs=1, tab=40 mm,
                                screw=0, clearance=0.1 mm, cx=0 mm, cy=tray_z)
    hole window { w = Slot(start=(0, 60), end=(0, 250), width=30) }
    Fillet([frame.top_left, frame.top_right], 10)
}

assembly stand {
    left = side()
    right = side()

    solid shelf {
        board = Rectangle(center=(0, 0), width=inner + 2 * ply, height=shelf_d)
        left_tenon = tab_and_slot(part="tab", length=70 mm, thickness=6 mm, tabs=1, tab=30 mm,
                                  screw=0, rotation=90 deg, cx=-inner / 2 - ply, cy=0 mm)
        right_tenon = tab_and_slot(part="tab", length=70 mm, thickness=6 mm, tabs=1, tab=30 mm,
                                   screw=0, rotation=-90 deg, cx=inner / 2 + ply, cy=0 mm)
        for i in range(6) {
            hole notch {
                s = Slot(start=(-2.5 * pitch + i * pitch, -shelf_d / 2 - 8),
                         end=(-2.5 * pitch + i * pitch, -8), width=16)
            }
        }
        drawing title { t = Text("PIPETTES", position=(0, 20), size=6, valign="middle") }
    }

    solid tray {
        board = Rectangle(center=(0, 0), width=inner + 2 * ply, height=tray_d)
        left_tenon = tab_and_slot(part="tab", length=110 mm, thickness=6 mm, tabs=1, tab=40 mm,
                                  screw=0, rotation=90 deg, cx=-inner / 2 - ply, cy=0 mm)
        right_tenon = tab_and_slot(part="tab", length=110 mm, thickness=6 mm, tabs=1, tab=40 mm,
                                   screw=0, rotation=-90 deg, cx=inner / 2 + ply, cy=0 mm)
        drawing labels {
            for i in range(6) {
                t = Text(names[i], position=(-2.5 * pitch + i * pitch, -45), size=5)
            }
        }
    }

    # 3D: sides stand in the y-z plane at x = -126 .. -120 and 120 .. 126
    Place(left, rotation=(90 deg, 0, 90 deg), position=(-inner / 2 - ply, 0, 0))
    Place(right, rotation=(90 deg, 0, 90 deg), position=(inner / 2, 0, 0))
    Place(shelf, position=(0, 0, shelf_z - ply / 2))
    Place(tray, position=(0, 0, tray_z - ply / 2))

    # flat on the sheet
    RightOf(right, left, gap=5)
    AlignBottom(right, left)
    RightOf(shelf, right, gap=5)
    AlignTop(shelf, right)
    Below(tray, shelf, gap=5)
    AlignLeft(tray, shelf)

    assert len(shelf.notch) == 6, "six notches"
    assert shelf.notch[1].s.center.x - shelf.notch[0].s.center.x == 38 mm, "38 mm apart"
    assert shelf.notch[0].s.width == 16 mm, "16 mm notches"
    assert shelf.notch[0].s.bb.top - shelf.board.bb.bottom == 35 mm, "35 mm deep from the front"
    assert left.frame.bb.height == 320 mm and left.frame.bottom_width == 120 mm and left.frame.top_width == 70 mm, "side 320 tall, 120 / 70 deep"
    assert left.shelf_mortise.bb.center_y - left.frame.bb.bottom == 300 mm, "shelf mid-plane 300 mm up"
    assert left.tray_mortise.bb.center_y - left.frame.bb.bottom == 18 mm, "tray mid-plane 18 mm up"
    assert shelf.board.bb.width - 2 * ply == 240 mm and tray.board.bb.height == 110 mm, "240 between the sides, tray 110 deep"
    assert len(tray.labels.t) == 6, "a label under each notch"
}
