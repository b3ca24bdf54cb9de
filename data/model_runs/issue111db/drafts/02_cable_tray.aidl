# Request: an under-desk cable tray for a power strip and chargers, 3 mm plywood, finger-jointed
# and glued. Outside 400 long x 100 deep x 80 high, open top. The back wall rises 30 mm above the
# tray as a mounting flange (top corners rounded 6 mm) with 3 countersunk M4 screws at 150 mm
# centres, 15 mm down from its top edge, sunk on the tray side (screwed to the desk's modesty
# panel). The bottom has a 2 x 10 grid of 30 x 6 mm slots (air and zip ties) at 36 mm along, 40 mm
# between rows, centred. Each end has a U notch for cables from the top edge: 40 mm wide, 30 mm
# deep, round bottom. "CABLES" is engraved 12 mm tall in the middle of the front.

import "std/joints.aidl"
import "std/fasteners.aidl"

thickness 3 mm

param length = 400 mm, min = 250 mm, max = 600 mm
param depth = 100 mm, min = 70 mm, max = 160 mm
param height = 80 mm, min = 50 mm, max = 120 mm
flange_h = 30 mm
notch_w = 40 mm
notch_depth = 30 mm
finger = 15 mm

def front_panel() -> solid {
    p = finger_panel(width=length, height=height, thickness=3 mm, finger=finger, top="flat")
    drawing label {
        word = Text("CABLES", position=(0, 0), size=12, valign="middle")
    }
}

def back_panel() -> solid {
    p = finger_panel(width=length, height=height, thickness=3 mm, finger=finger, top="flat")
    flange = RoundedRectangle(center=(0, height / 2 + flange_h / 2), width=length, height=flange_h,
                              corner_radii=[6, 6, 0, 0])
    screw = clearance_hole(size=4)
    screw.c.center == (-150, height / 2 + flange_h - 15)
    screws = LinearPattern(screw, 3, (150, 0))
    Countersink(screws, diameter=9 mm)
}

def end_panel() -> solid {
    p = finger_panel(width=depth, height=height, thickness=3 mm, finger=finger,
                     bottom="slots", right="slots", top="flat", left="slots")
    hole notch {
        n = Slot(start=(0, height / 2 - notch_depth + notch_w / 2), end=(0, height / 2 + notch_w / 2),
                 width=notch_w)
    }
}

def bottom_panel() -> solid {
    p = finger_panel(width=length, height=depth, thickness=3 mm, finger=finger,
                     bottom="slots", right="fingers", top="slots", left="fingers")
    hole vent {
        s = Slot(center=(-162, -20), length=30, width=6)
    }
    vents = GridPattern(vent, 2, 10, (36, 40))
}

assembly cable_tray {
    bottom = bottom_panel()
    front = front_panel()
    back = back_panel()
    left = end_panel()
    right = end_panel()

    # flat on the sheet: a net round the bottom
    Fixed(bottom)
    Below(front, bottom, gap=5)
    AlignCenterX(front, bottom)
    Above(back, bottom, gap=5)
    AlignCenterX(back, bottom)
    LeftOf(left, bottom, gap=5)
    AlignCenterY(left, bottom)
    RightOf(right, bottom, gap=5)
    AlignCenterY(right, bottom)

    # in 3D: standing on z = 0, centred on x = y = 0
    Place(bottom, position=(0, 0, 0), face="up")
    Place(front, position=(0, -depth / 2 + 3 mm, height / 2), face="front", up="up")
    Place(back, position=(0, depth / 2, height / 2), face="front", up="up")
    Place(left, position=(-length / 2 + 3 mm, 0, height / 2), face="left", up="up")
    Place(right, position=(length / 2 - 3 mm, 0, height / 2), face="right", up="up")

    assert bottom.p.outline.width == 400 mm and bottom.p.outline.height == 100 mm, "400 x 100 outside"
    assert front.p.outline.height == 80 mm, "80 high"
    assert back.flange.bb.top - back.p.outline.bb.top == 30 mm, "flange 30 mm above the tray"
    assert len(back.screws) == 3, "3 screws"
    assert back.screws[1].c.center.x - back.screws[0].c.center.x == 150 mm, "screws at 150 mm centres"
    assert back.flange.bb.top - back.screws[0].c.center.y == 15 mm, "screws 15 mm down"
    assert len(bottom.vents) == 20, "2 x 10 slots"
    assert abs(bottom.vents[0].s.center.x + bottom.vents[19].s.center.x) < 0.01 mm, "slots centred"
    assert left.notch.n.width == 40 mm, "notch 40 wide"
    assert left.p.outline.bb.top - left.notch.n.bb.bottom == 30 mm, "notch 30 deep"
}
