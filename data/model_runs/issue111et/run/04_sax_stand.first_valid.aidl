# Request: a flat-pack stand for my alto saxophone, two 6 mm birch-ply plates that slot
# together crosswise (a cross halving) into a four-armed peg that goes up inside the bell.
# Each plate: a foot 260 mm wide and 45 mm tall, its two top outer corners rounded R10, a
# 160 mm wide, 8 mm high relief under its middle so it stands on two feet; on the foot a
# tapered peg 100 mm wide at the foot narrowing to a round top of R35 whose top is 230 mm
# above the floor, blended into the foot with R12 fillets (the bell's rim rests on the
# four shoulders; the bell is about 120 mm across inside). Plate A has its halving slot
# from the top of the peg, plate B from its bottom relief; each slot is half the height
# where the plates cross, 6 mm wood + 0.2 mm clearance wide. "ALTO" engraved, filled,
# 12 mm tall on the right of plate A's foot.

import "std/joints.aidl"

units mm
t = 6 mm
thickness t
kerf 0.15 mm

foot_w = 260 mm
foot_h = 45 mm
relief_w = 160 mm
relief_h = 8 mm
peg_w = 100 mm
top_r = 35 mm
peg_top = 230 mm
overlap = peg_top - relief_h          # where the two plates cross, on the centre line
slot_depth = overlap / 2

def stand_plate(slot_from_top=true) -> solid {
    foot = Rectangle(bottom_left=(-foot_w / 2, 0), width=foot_w, height=foot_h)
    peg = Hull(Point(-peg_w / 2, foot_h), Point(peg_w / 2, foot_h),
               Circle(center=(0, peg_top - top_r), radius=top_r))
    Fillet([foot.top_left, foot.top_right], 10)
    Fillet([(-peg_w / 2, foot_h), (peg_w / 2, foot_h)], 12)
    hole relief {
        r = Rectangle(center=(0, 0), width=relief_w, height=2 * relief_h, overrun=true)
    }
    if slot_from_top {
        slot = cross_halving(depth=slot_depth, thickness=t, clearance=0.2 mm, cx=0, cy=peg_top)
        drawing mark {
            word = Text("ALTO", position=(foot_w / 2 - 45 mm, foot_h / 2), size=12, font="sans:Bold",
                        valign="middle", fill=true)
        }
    } else {
        slot = cross_halving(depth=slot_depth, thickness=t, clearance=0.2 mm, rotation=180 deg,
                             cx=0, cy=relief_h)
    }
}

assembly sax_stand {
    a = stand_plate(slot_from_top=true)
    b = stand_plate(slot_from_top=false)
    RightOf(b, a, gap=10)
    AlignBottom(b, a)

    # standing crossed: A across the x axis, B across the y axis, both centred on z
    Place(a, position=(0, t / 2, 0), face="front", up="up")
    Place(b, position=(-t / 2, 0, 0), face="right", up="up")

    assert a.foot.width == 260 mm and a.foot.height == 45 mm
    assert a.peg.bb.top - a.foot.bb.bottom == 230 mm, "peg top 230 mm above the floor"
    assert a.peg.bb.width == 100 mm, "peg 100 mm wide at the foot"
    assert a.relief.r.width == 160 mm and a.relief.r.bb.top - a.foot.bb.bottom == 8 mm
    assert a.slot.depth + b.slot.depth == 230 mm - 8 mm, "the slots add up to the crossing"
    assert a.slot.cut.bb.width == 6.2 mm, "6 mm ply + 0.2 mm clearance"
    assert a.slot.cut.bb.top == a.peg.bb.top, "A's slot from the top"
    assert b.slot.cut.bb.bottom - b.foot.bb.bottom == 8 mm, "B's slot from the relief"
    assert a.peg.bb.width < 120 mm, "the peg goes inside the bell"
    assert a.mark.word.size == 12 mm
    assert distance(a.mark, a.peg) >= 3 mm, "ALTO clear of the peg"
}
