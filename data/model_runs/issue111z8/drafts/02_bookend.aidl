# Office: a desk bookend of 3 mm plywood, two glued parts.
# Upright 140 wide x 170 tall, its top corners rounded R20, a 30 mm finger hole
# centred 40 mm below the top, "BOOKS" engraved 10 mm tall with its baseline
# 75 mm below the top. Its bottom edge has 2 glued tabs 25 mm wide (no screws).
# Base 140 x 110 (front corners R10) with the 2 matching mortises; the upright's
# middle stands 6.5 mm in from the base's back edge (the top edge as drawn).

units mm
thickness 3 mm

import "std/joints.aidl"

assembly bookend {
    solid upright {
        body = RoundedRectangle(center=(0, 0), width=140, height=170, corner_radii=[20, 20, 0, 0])
        tabs = tab_and_slot(part="tab", length=140 mm, thickness=3 mm, tabs=2, tab=25 mm,
                            screw=0, rotation=180 deg, cx=0 mm, cy=-85 mm)
        hole grip {
            c = Circle(center=(0, 85 - 40), diameter=30)
        }
        drawing label {
            t = Text("BOOKS", position=(0, 85 - 75), size=10)
        }
    }

    solid base {
        body = RoundedRectangle(center=(0, 0), width=140, height=110, corner_radii=[0, 0, 10, 10])
        mortise = tab_and_slot(part="slot", length=140 mm, thickness=3 mm, tabs=2, tab=25 mm,
                               screw=0, cx=0 mm, cy=55 - 6.5)
    }
    RightOf(base, upright, gap=10)
    AlignBottom(base, upright)

    assert upright.body.bb.width == 140 mm and upright.body.bb.height == 170 mm, "upright 140 x 170"
    assert base.body.bb.width == 140 mm and base.body.bb.height == 110 mm, "base 140 x 110"
    assert upright.grip.c.diameter == 30 mm, "finger hole 30"
    assert upright.body.bb.top - upright.grip.c.center.y == 40 mm, "finger hole 40 below the top"
    assert upright.body.bb.top - upright.label.t.position.y == 75 mm, "label baseline 75 below the top"
    assert base.body.bb.top - base.mortise.bb.center_y == 6.5 mm, "mortises 6.5 in from the back"
    assert upright.tabs.tab == 25 mm and upright.tabs.tabs == 2, "2 tabs of 25"
}
