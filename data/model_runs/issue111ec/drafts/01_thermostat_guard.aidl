# Request (home): a tamper guard over the hall thermostat, from 3 mm ply.
# A finger-jointed closed box 130 x 130 x 40 mm outside (10 mm fingers). The bottom panel
# is the wall plate: a 92 x 92 mm opening fits round the 88 x 88 mm thermostat, and four
# M4 countersunk screw holes (8.5 mm heads), 11 mm in from each outer edge, screw it to the
# wall from inside. The lid is the guard's face: a 44 mm round window to read the display,
# its centre 18 mm above the lid's centre; "PLEASE DO NOT ADJUST" engraved filled (sans bold,
# 7 mm) under it; seven vent slots 4 x 24 mm, 12 mm apart, standing 12 mm above the lid's
# bottom edge.

import "std/joints.aidl"

thickness 3 mm

param t = 3 mm, min = 2 mm, max = 6 mm
side = 130 mm
depth = 40 mm
opening = 92 mm
screw_in = 11 mm
corners = [[-1, -1], [1, -1], [1, 1], [-1, 1]]

assembly guard {
    box = finger_box(length=side, depth=side, height=depth, thickness=t, finger=10 mm)

    # wall plate: opening round the thermostat and four screw holes
    hole opening_cut {
        r = Rectangle(center=(0, 0), width=opening, height=opening)
    }
    CenterInside(opening_cut, box.bottom)
    CutInto(opening_cut, box.bottom)

    hole screws {
        for k in range(4) {
            c = Circle(center=(corners[k][0] * (side / 2 - screw_in),
                               corners[k][1] * (side / 2 - screw_in)), diameter=4.5)
        }
    }
    Rigid(screws)
    CenterInside(screws, box.bottom)
    CutInto(screws, box.bottom)
    Countersink(screws, diameter=8.5 mm)

    # the face: window, notice, vents
    hole window {
        c = Circle(center=(0, 0), diameter=44)
    }
    AlignCenterX(window, box.lid)
    window.c.center.y == box.lid.bb.center_y + 18 mm
    CutInto(window, box.lid)

    drawing notice {
        words = Text("PLEASE DO NOT ADJUST", position=(0, 0), size=7, font="sans:Bold",
                     valign="middle", fill=true, max_width=110 mm)
    }
    AlignCenterX(notice, box.lid)
    notice.words.position.y == (window.bb.bottom + vents.bb.top) / 2
    CutInto(notice, box.lid)

    hole vents {
        for i in range(7) {
            s = Slot(center=(i * 12 mm, 0), length=24, width=4, rotation=90)
        }
    }
    Rigid(vents)
    AlignCenterX(vents, box.lid)
    vents.bb.bottom == box.lid.bb.bottom + 12 mm
    CutInto(vents, box.lid)

    # the request's own numbers
    assert box.front.bb.width == 130 mm, "guard 130 wide"
    assert box.front.bb.height == 40 mm, "guard 40 deep"
    assert opening_cut.bb.width == 92 mm, "opening 92 for an 88 mm thermostat"
    assert opening_cut.bb.width >= 88 mm + 2 mm, "thermostat fits with play"
    assert len(vents.s) == 7, "seven vents"
    assert vents.s[1].center.x - vents.s[0].center.x == 12 mm, "vents 12 apart"
    assert vents.bb.bottom - box.lid.bb.bottom == 12 mm, "vents 12 above the edge"
    assert window.c.center.y - box.lid.bb.center_y == 18 mm, "window 18 above centre"
    assert screws.c[0].center.x - box.bottom.bb.left == 11 mm, "screws 11 in"
    assert screws.c[0].center.y - box.bottom.bb.bottom == 11 mm, "screws 11 in"
    # countersinks clear the walls and the opening
    assert screws.c[0].center.x - 8.5 mm / 2 >= box.bottom.bb.left + t + 1 mm, "head clears the wall"
    assert screws.c[0].center.x + 8.5 mm / 2 <= opening_cut.bb.left - 1 mm, "head clears the opening"
    assert distance(notice, window) >= 3 mm, "notice clear of the window"
    assert distance(notice, vents) >= 3 mm, "notice clear of the vents"
    assert notice.bb.width <= 110 mm, "notice within the face"
}
