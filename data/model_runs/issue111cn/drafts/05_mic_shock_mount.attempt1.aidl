# Request (music): a shock mount for my 48 mm diameter condenser microphone, from 3 mm
# plywood. Two identical frames: an outer ring 110 mm across and 10 mm wide with eight 3 mm
# cord holes on its middle circle, and a 30 mm wide stem below it ending 80 mm below the
# ring's centre in one 14 mm tab. Two inner rings that grip the mic: 48 mm bore, 64 mm
# outside, eight 3 mm cord holes on a 56 mm circle, lined up with the outer ones so the
# elastic cord runs straight out. A 50 x 76 mm bridge joins the two stems 60 mm apart (glued
# tabs in slots) and has a 22 mm hole in the middle for a 5/8"-27 threaded insert that takes
# the mic stand. Cut the inner rings from the frames' centres to save plywood; show it
# assembled.

import "std/joints.aidl"

thickness 3 mm

param mic_d = 48 mm, min = 30 mm, max = 60 mm
param spacing = 60 mm, min = 40 mm, max = 90 mm

cord_angles = [22.5 deg + k * 45 deg for k in range(8)]

def frame() -> solid {
    rim = Shell(Circle(center=(0, 0), radius=45), 10)
    stem = Rectangle(center=(0, -64), width=30, height=32)
    hole cords {
        for k in range(8) {
            c = Circle(center=polar((0, 0), 50, cord_angles[k]), diameter=3)
        }
    }
    foot = tab_and_slot(part="tab", length=30 mm, thickness=3 mm, tabs=1, tab=14 mm, screw=0,
                        rotation=180 deg, cx=0 mm, cy=-80 mm)
}

def inner_ring() -> solid {
    band = Shell(Circle(center=(0, 0), radius=mic_d / 2), 8)
    hole cords {
        for k in range(8) {
            c = Circle(center=polar((0, 0), 28, cord_angles[k]), diameter=3)
        }
    }
}

assembly shock_mount {
    front = frame()
    back = frame()
    grip_front = inner_ring()
    grip_back = inner_ring()

    solid bridge {
        plate = Rectangle(center=(0, 0), width=50, height=76)
        s_front = tab_and_slot(part="slot", length=30 mm, thickness=3 mm, tabs=1, tab=14 mm,
                               screw=0, cx=0 mm, cy=-spacing / 2)
        s_back = tab_and_slot(part="slot", length=30 mm, thickness=3 mm, tabs=1, tab=14 mm,
                              screw=0, cx=0 mm, cy=spacing / 2)
        hole insert { c = Circle(center=(0, 0), diameter=22) }
    }

    # on the sheet: the grips nest inside the frames, the bridge under them
    RightOf(back, front, gap=8)
    AlignCenterY(back, front)
    Concentric(grip_front.band, front.rim)
    Concentric(grip_back.band, back.rim)
    Below(bridge, front, gap=8)
    AlignCenterX(bridge, front)

    # assembled: frames stand up, their tabs through the bridge lying flat
    Place(bridge, position=(0, 0, 0))
    Place(front, position=(0, -spacing / 2 + 1.5 mm, 80), face="front", up="up")
    Place(back, position=(0, spacing / 2 - 1.5 mm, 80), face="back", up="up")
    Place(grip_front, position=(0, -spacing / 2 + 1.5 mm, 80), face="front", up="up")
    Place(grip_back, position=(0, spacing / 2 - 1.5 mm, 80), face="back", up="up")

    assert front.rim.bb.width == 110 mm, "outer ring 110 across"
    assert grip_front.band.bb.width == 64 mm, "inner ring 64 outside"
    assert len(front.cords.c) == 8 and len(grip_front.cords.c) == 8
    assert distance(grip_front.cords.c[0].center, grip_front.cords.c[4].center) == 56 mm
    assert front.rim.bb.center_y - front.stem.bb.bottom == 80 mm, "stem ends 80 below centre"
    assert bridge.plate.width == 50 mm and bridge.plate.height == 76 mm
    assert bridge.s_back.slot[0].bb.center_y - bridge.s_front.slot[0].bb.center_y == 60 mm
    assert bridge.insert.c.diameter == 22 mm
}
