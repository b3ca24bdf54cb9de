# Request: a wall rack for three 18 V slide-pack drill batteries, cut from 6 mm birch ply.
# A back plate 330 x 140 mm with R6 corners hangs on two keyholes (9 mm head, 4.5 mm slot,
# 10 mm long, heads 32 mm below the top edge and 145 mm either side of the middle).
# Three docks 100 mm apart (centres), each a T-rail the battery slides down onto:
# a stem 22 mm wide and 70 mm long with a 34 x 8 mm stop foot at its bottom, glued to the
# back plate, and a cap 34 x 70 mm (R2 corners) glued on the stem, so the cap overhangs the
# stem 6 mm each side for the battery's grooves. The back plate has each cap's footprint
# engraved as a glue-up guide and "BATTERIES" engraved filled (10 mm, bold) under the docks;
# each cap has "18V" and its number 1-3 engraved filled.

import "std/plates.aidl"

thickness 6 mm

param pitch = 100 mm, min = 60 mm, max = 110 mm
rail_w = 22 mm
cap_w = 34 mm
rail_len = 70 mm
foot_h = 8 mm
dock_cy = 5 mm

def dock_x(i) = (i - 1) * pitch

def stem(x0=0 mm) -> solid {
    rail = Rectangle(center=(x0, dock_cy), width=rail_w, height=rail_len)
    foot = Rectangle(center=(x0, dock_cy - rail_len / 2 + foot_h / 2), width=cap_w, height=foot_h)
}

def cap(x0=0 mm, label="1") -> solid {
    plate = RoundedRectangle(center=(x0, dock_cy), width=cap_w, height=rail_len, corner_radius=2)
    drawing mark {
        volts = Text("18V", position=(x0, dock_cy + 18), size=6, font="sans:Bold", fill=true,
                     valign="middle")
        num = Text(label, position=(x0, dock_cy - 8), size=14, font="sans:Bold", fill=true,
                   valign="middle")
    }
}

assembly rack {
    solid back {
        body = RoundedRectangle(center=(0, 0), width=330, height=140, corner_radius=6)
        k_left = keyhole(head=9, slot_width=4.5, length=10, cx=-145, cy=70 - 32)
        k_right = keyhole(head=9, slot_width=4.5, length=10, cx=145, cy=70 - 32)
        drawing guides {
            for i in range(3) {
                g = Rectangle(center=(dock_x(i), dock_cy), width=cap_w, height=rail_len)
            }
            title = Text("BATTERIES", position=(0, -55), size=10, font="sans:Bold", fill=true)
        }
    }
    for i in range(3) {
        s = stem(x0=dock_x(i))
        c = cap(x0=dock_x(i), label=str(i + 1))
        # on the sheet: stems in a row under the back plate, caps under the stems
        Below(s, back, gap=6)
        Below(c, s, gap=6)
        # in 3D: stem glued on the back plate's face, cap on the stem
        Place(s, position=(0, -6, 0), face="front")
        Place(c, position=(0, -12, 0), face="front")
    }
    Place(back, position=(0, 0, 0), face="front")

    # the request's numbers
    assert back.body.width == 330 mm and back.body.height == 140 mm, "back plate 330 x 140"
    assert len(s) == 3 and len(c) == 3, "three docks"
    assert s[1].rail.center.x - s[0].rail.center.x == 100 mm, "docks 100 apart"
    assert (c[0].plate.width - s[0].rail.width) / 2 == 6 mm, "cap overhangs the stem 6 mm a side"
    assert s[0].foot.width == 34 mm and s[0].foot.height == 8 mm, "stop foot 34 x 8"
    assert back.k_right.head_hole.center.x - back.k_left.head_hole.center.x == 290 mm,
        "keyholes 145 either side"
    assert back.body.bb.top - back.k_left.head_hole.center.y == 32 mm, "keyheads 32 below the top"
    assert distance(back.guides.title, back.guides.g[0]) >= 3 mm, "title clear of the docks"
    assert distance(back.k_left, back.guides.g[0]) >= 5 mm, "keyhole clear of the dock"
}
