# Request (kitchen): a butter dish for a 250 g block (125 x 65 x 35 mm), cut from 3 mm clear
# acrylic. A base plate 190 x 110 mm with R10 corners, and a rim layer of the same outline glued
# on top of it with a rectangular opening 162 x 87 mm that the cover drops into (1 mm all round).
# The cover is a finger-jointed box 160 x 85 x 50 mm outside (10 mm fingers), open at the bottom
# (an open-top box turned over). On its top a D-shaped knob, 60 mm long, standing 22 mm proud
# with R11 top corners, glued into the cover by two 12 mm tabs in mortises. BUTTER engraved
# (bold, filled, 14 mm) on the cover's front, reading the right way up when the cover is on.

import "std/joints.aidl"

thickness 3 mm

param t = 3 mm, min = 2 mm, max = 4 mm
cover_l = 160 mm
cover_d = 85 mm
cover_h = 50 mm
knob_l = 60 mm
knob_h = 22 mm

assembly butter_dish {
    box = finger_box(length=cover_l, depth=cover_d, height=cover_h, thickness=t, finger=10 mm,
                     closed=false, cx=0, cy=0)

    # the knob's mortises in the box's bottom panel (the cover's top once turned over)
    hole mortise {
        m = tab_and_slot(part="slot", length=knob_l, thickness=t, tabs=2, tab=12 mm, screw=0,
                         cx=0, cy=0)
    }
    CutInto(mortise, box.bottom)

    # BUTTER on the back panel of the net, turned 180 deg: the cover is used upside down,
    # so the back's outside face becomes the front and the text reads the right way up
    drawing label {
        word = Text("BUTTER", position=(0, 0), size=14, font="sans:Bold", valign="middle",
                    rotation=180 deg, fill=true)
    }
    CenterInside(label, box.back)
    CutInto(label, box.back)

    solid knob {
        grip = RoundedRectangle(bottom_left=(-knob_l / 2, -t), width=knob_l, height=knob_h + t,
                                corner_radii=[11, 11, 0, 0])
        tabs = tab_and_slot(part="tab", length=knob_l, thickness=t, tabs=2, tab=12 mm, screw=0,
                            rotation=180 deg, cx=0, cy=-t)
    }

    solid base {
        plate = RoundedRectangle(center=(0, 0), width=190, height=110, corner_radius=10)
    }
    solid rim {
        plate = RoundedRectangle(center=(0, 0), width=190, height=110, corner_radius=10)
        hole opening { r = Rectangle(center=(0, 0), width=162, height=87) }
    }

    # flat on the sheet
    RightOf(base, box, gap=10)
    AlignTop(base, box)
    Below(rim, base, gap=10)
    AlignLeft(rim, base)
    Below(knob, box, gap=10)
    AlignLeft(knob, box)

    # assembled: base, rim on it, the cover turned over into the rim, the knob on top
    Place(base, position=(0, 0, 0))
    Place(rim, position=(0, 0, t))
    Place(box, position=(0, 0, t + cover_h), rotation=(180 deg, 0, 0))
    Place(knob, position=(0, t / 2, t + cover_h), face="front", up="up")

    # the request's numbers
    assert base.plate.width == 190 mm and base.plate.height == 110 mm, "base 190 x 110"
    assert rim.opening.r.width == 162 mm and rim.opening.r.height == 87 mm, "opening 162 x 87"
    assert rim.opening.r.width - box.bottom.bb.width == 2 mm, "1 mm clearance all round (length)"
    assert box.front.bb.width == 160 mm, "cover 160 mm long"
    assert box.front.bb.height == 50 mm, "cover 50 mm tall"
    assert cover_l - 2 * t >= 125 mm + 10 mm, "a 250 g block fits lengthwise with room"
    assert cover_d - 2 * t >= 65 mm + 10 mm, "a 250 g block fits across with room"
    assert cover_h - t >= 35 mm + 5 mm, "a 250 g block fits under the top"
    assert knob.grip.bb.top - knob.tabs.gap[0].bb.top == 22 mm, "knob stands 22 mm proud"
    assert len(mortise.m.slot) == 2, "two mortises"
}
