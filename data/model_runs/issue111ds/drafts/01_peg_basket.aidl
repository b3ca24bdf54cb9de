# Request (home, laundry): a clothes-peg basket that hangs on the washing line.
# 4 mm exterior ply. An open-top finger-jointed box 180 long x 100 deep x 110 tall
# (outside), 15 mm fingers. Six 3 x 6 drain holes of 8 mm on a 24 mm pitch in the bottom.
# "PEGS" cut through the front as 35 mm bold stencil letters, centred.
# A hook plate 170 wide stands inside against the back, on the bottom, and rises 50 mm
# above the rim; its top corners R10. Two hook slots, 12 mm wide, 35 mm deep, 120 mm
# apart, cut down from its top edge, take the line. The plate is bolted to the back by
# two M4 bolts 120 mm apart, 25 mm below the rim (the same holes in the back panel).

import "std/joints.aidl"
import "std/fasteners.aidl"

thickness 4 mm

param box_l = 180 mm, min = 140 mm, max = 260 mm
param box_d = 100 mm, min = 80 mm, max = 140 mm
param box_h = 110 mm, min = 90 mm, max = 150 mm
param t = 4 mm, min = 3 mm, max = 6 mm
param rise = 50 mm, min = 40 mm, max = 80 mm
param bolt_drop = 25 mm, min = 15 mm, max = 40 mm
param pitch = 120 mm, min = 80 mm, max = 140 mm

plate_h = box_h - t + rise

assembly peg_basket {
    box = finger_box(length=box_l, depth=box_d, height=box_h, thickness=t, finger=15 mm,
                     closed=false)

    # drain holes in the bottom
    hole drains {
        d = Circle(center=(0, 0), diameter=8)
        g = GridPattern(d, 3, 6, (24, 24))
    }
    CenterInside(drains, box.bottom)
    CutInto(drains, box.bottom)

    # the word cut through the front
    hole label {
        t = Text("PEGS", position=(0, 0), size=35, font="sans:Bold", valign="middle",
                 stencil=true)
    }
    CenterInside(label, box.front)
    CutInto(label, box.front)

    # the two bolt holes in the back, 25 mm below the rim
    hole back_bolts {
        l = clearance_hole(size=4, cx=-pitch / 2, cy=0)
        r = clearance_hole(size=4, cx=pitch / 2, cy=0)
    }
    AlignCenterX(back_bolts, box.back)
    back_bolts.l.c.center.y == box.back.bb.bottom + box_h - bolt_drop
    CutInto(back_bolts, box.back)

    # the hook plate: its own (0, 0) is the middle of its bottom edge
    solid hook_plate {
        body = RoundedRectangle(center=(0, plate_h / 2), width=170, height=plate_h,
                                corner_radii=[10, 10, 0, 0])
        hole hooks {
            for i in range(2) {
                s = Slot(start=(-pitch / 2 + i * pitch, plate_h + 10),
                         end=(-pitch / 2 + i * pitch, plate_h - 35 + 6), width=12,
                         overrun=true)
            }
        }
        b1 = clearance_hole(size=4, cx=-pitch / 2, cy=box_h - t - bolt_drop)
        b2 = clearance_hole(size=4, cx=pitch / 2, cy=box_h - t - bolt_drop)
    }
    RightOf(hook_plate, box, gap=10)
    AlignBottom(hook_plate, box)

    # assembled: standing on the bottom panel, against the inside of the back
    Place(hook_plate, position=(0, box_d / 2 - t, t), face="front", up="up")

    # the request's numbers
    assert hook_plate.body.bb.height - (110 mm - 4 mm) == 50 mm, "rises 50 mm above the rim"
    assert hook_plate.body.bb.width <= 180 mm - 2 * 4 mm, "fits between the sides"
    assert hook_plate.hooks.s[1].end.x - hook_plate.hooks.s[0].end.x == 120 mm, "hooks 120 apart"
    assert hook_plate.body.bb.top - (hook_plate.hooks.s[0].end.y - 12 mm / 2) == 35 mm,
        "hooks 35 mm deep"
    assert hook_plate.b2.c.center.x - hook_plate.b1.c.center.x == 120 mm, "bolts 120 apart"
    assert (hook_plate.b1.c.center.y - hook_plate.body.bb.bottom) + 4 mm ==
        110 mm - 25 mm, "plate bolts 25 mm below the rim"
    assert back_bolts.l.c.center.y - box.back.bb.bottom == 110 mm - 25 mm,
        "back bolts 25 mm below the rim"
    assert len(drains.g) == 18, "3 x 6 drain holes"
}
