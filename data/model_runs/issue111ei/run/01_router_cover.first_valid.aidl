# Request (home): a cover to hide our broadband router on the hall shelf. The router is
# 260 wide, 180 deep and 45 tall with its lights on the front, 25 mm up. I want a 3 mm ply
# box with no bottom and no back (the cables come out of the back, it just sits over the
# router): inside 280 wide, 190 deep, 70 tall. Finger-jointed top, front and two sides.
# The top gets a grid of vent slots: 5 rows of 8 slots, each 24 long and 5 wide, 30 mm
# apart along a row and 14 mm between rows, centred. The front gets a 160 x 14 round-ended
# window centred 25 mm above the shelf so I can still see the lights, and WI-FI engraved
# filled (sans bold, 14 mm caps) centred above the window, 12 mm clear of it. Each side
# gets 4 upright vent slots, 40 long and 6 wide, 20 mm apart, centred on the side.

import "std/joints.aidl"

thickness 3 mm

param t = 3 mm, min = 2 mm, max = 6 mm
inside_w = 280 mm
inside_d = 190 mm
inside_h = 70 mm
L = inside_w + 2 * t     # outer width: a side wall each end
D = inside_d + t         # outer depth: the front wall only, the back is open
H = inside_h + t         # outer height: the top only, the bottom is open

assembly router_cover {
    # the top: slots on the front edge, fingers into the sides, plain back
    top = finger_panel(width=L, height=D, thickness=t, finger=12 mm,
                       bottom="slots", right="fingers", top="flat", left="fingers")
    # the front: fingers all round except the plain bottom edge on the shelf
    front = finger_panel(width=L, height=H, thickness=t, finger=12 mm,
                         bottom="flat", right="fingers", top="fingers", left="fingers")
    # sides lie with the front edge toward the front in 3D: the left side's drawing +x
    # points to the front, the right side's to the back
    left = finger_panel(width=D, height=H, thickness=t, finger=12 mm,
                        bottom="flat", right="slots", top="slots", left="flat")
    right = finger_panel(width=D, height=H, thickness=t, finger=12 mm,
                         bottom="flat", right="flat", top="slots", left="slots")

    # vents in the top, centred on it
    hole vent { s = Slot(center=(0, 0), length=24, width=5) }
    vents = GridPattern(vent, 5, 8, (30, 14))
    At(vent.s.center, top.outline.center, dx=-3.5 * 30, dy=-2 * 14)
    CutInto(vent, top)

    # the light window and the label on the front
    hole window { s = Slot(center=(0, 0), length=160, width=14) }
    AlignCenterX(window, front.outline)
    window.s.center.y == front.outline.bb.bottom + 25 mm
    CutInto(window, front)

    drawing label {
        t1 = Text("WI-FI", position=(0, 0), size=14, font="sans:Bold", valign="middle", fill=true)
    }
    AlignCenterX(label, front.outline)
    label.bb.bottom == window.bb.top + 12 mm
    CutInto(label, front)

    # four upright vent slots in each side
    hole lvent { s = Slot(center=(0, 0), length=40, width=6, rotation=90) }
    lvents = LinearPattern(lvent, 4, (20, 0))
    At(lvent.s.center, left.outline.center, dx=-1.5 * 20)
    CutInto(lvent, left)
    hole rvent { s = Slot(center=(0, 0), length=40, width=6, rotation=90) }
    rvents = LinearPattern(rvent, 4, (20, 0))
    At(rvent.s.center, right.outline.center, dx=-1.5 * 20)
    CutInto(rvent, right)

    # laid out flat for cutting
    Below(front, top, gap=6)
    AlignCenterX(front, top)
    Below(left, front, gap=6)
    AlignLeft(left, front)
    RightOf(right, left, gap=6)
    AlignTop(right, left)

    # assembled: the box sits on z = 0, centred on x = 0, its front face at y = -D / 2
    Place(top, position=(0, 0, H - t), face="up")
    Place(front, position=(0, -D / 2 + t, H / 2), face="front", up="up")
    Place(left, position=(-L / 2 + t, 0, H / 2), face="left", up="up")
    Place(right, position=(L / 2 - t, 0, H / 2), face="right", up="up")

    # the request's numbers
    assert top.outline.bb.width - 2 * t >= 280 mm, "fits 280 inside across"
    assert top.outline.bb.height - t >= 190 mm, "fits 190 inside deep"
    assert front.outline.bb.height - t >= 70 mm, "fits 70 inside tall"
    assert len(vents) == 40, "5 rows of 8 top vents"
    assert len(lvents) == 4 and len(rvents) == 4, "4 vents a side"
    assert window.s.center.y - front.outline.bb.bottom == 25 mm, "window 25 up"
    assert label.bb.bottom - window.bb.top >= 12 mm, "label clear of the window"
    assert vents[39].s.center.x - vents[0].s.center.x == 7 * 30 mm, "row pitch 30"
}
