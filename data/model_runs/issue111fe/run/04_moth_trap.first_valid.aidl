# Request (garden): the top of a bucket moth trap, for recording the garden's moths.
# - lid: a 340 mm disc of 6 mm ply that sits on a 30 litre bucket, a 70 mm entrance hole in
#   the middle (a funnel drops into it), "GARDEN MOTH TRAP" engraved filled round the top of
#   the rim (10 mm letters) and "RELEASE AT DUSK" under it (8 mm, readable).
# - two vanes of 3 mm clear acrylic, 220 wide x 250 tall, cross-halved at the centre (one
#   slotted up from its foot, the other down from its bulb notch, 0.2 mm clearance), each
#   with two 25 mm tenons at its foot into the lid and two at its head into the cap; a
#   70 x 120 notch at the top centre of both leaves room for the hanging bulb (A60, 60 mm).
# - cap / rain hat: a 240 mm disc of 6 mm ply on the vanes' heads with a 40 mm hole for
#   the lamp holder.

units mm
thickness 6 mm

import "std/joints.aidl"

ply = 6 mm
acrylic = 3 mm
vane_w = 220 mm
vane_h = 250 mm
notch_w = 70 mm
notch_depth = 120 mm
crossing = vane_h - notch_depth     # where both vanes are whole: 130 mm
tenon = 25 mm

def vane(from_top=false) -> solid {
    thickness 3 mm
    body = Rectangle(center=(0, 125), width=220, height=262)
    foot = tab_and_slot(part="tab", length=220 mm, thickness=6 mm, tabs=2, tab=25 mm,
                        screw=0, rotation=180 deg, cx=0 mm, cy=-6 mm)
    head = tab_and_slot(part="tab", length=220 mm, thickness=6 mm, tabs=2, tab=25 mm,
                        screw=0, rotation=0 deg, cx=0 mm, cy=256 mm)
    hole bulb {
        n = Rectangle(center=(0, 130 + 123 / 2), width=70, height=123)
    }
    if from_top {
        halving = cross_halving(depth=65 mm, thickness=3 mm, clearance=0.2 mm,
                                rotation=0 deg, cx=0 mm, cy=130 mm)
    } else {
        halving = cross_halving(depth=65 mm, thickness=3 mm, clearance=0.2 mm,
                                rotation=180 deg, cx=0 mm, cy=0 mm)
    }
}

assembly moth_trap {
    solid lid {
        disc = Circle(center=(0, 0), diameter=340)
        hole funnel {
            c = Circle(center=(0, 0), diameter=70)
        }
        mortise_a = tab_and_slot(part="slot", length=220 mm, thickness=3 mm, tabs=2,
                                 tab=25 mm, screw=0, clearance=0.2 mm, cx=0 mm, cy=0 mm)
        mortise_b = tab_and_slot(part="slot", length=220 mm, thickness=3 mm, tabs=2,
                                 tab=25 mm, screw=0, clearance=0.2 mm, rotation=90 deg,
                                 cx=0 mm, cy=0 mm)
        drawing words {
            top_ring = Circle(center=(0, 0), radius=148, construction=true)
            bottom_ring = Circle(center=(0, 0), radius=158, construction=true)
            title = Text("GARDEN MOTH TRAP", along=top_ring, size=10, font="sans:Bold",
                         fill=true)
            note = Text("RELEASE AT DUSK", along=bottom_ring, size=8, font="sans:Bold",
                        fill=true, flip=true)
        }
    }

    vane_a = vane(from_top=false)
    vane_b = vane(from_top=true)

    solid cap {
        disc = Circle(center=(0, 0), diameter=240)
        hole lampholder {
            c = Circle(center=(0, 0), diameter=40)
        }
        mortise_a = tab_and_slot(part="slot", length=220 mm, thickness=3 mm, tabs=2,
                                 tab=25 mm, screw=0, clearance=0.2 mm, cx=0 mm, cy=0 mm)
        mortise_b = tab_and_slot(part="slot", length=220 mm, thickness=3 mm, tabs=2,
                                 tab=25 mm, screw=0, clearance=0.2 mm, rotation=90 deg,
                                 cx=0 mm, cy=0 mm)
    }

    # 3D: lid on the bucket, vane a along x, vane b along y, the cap on their heads
    Place(lid, position=(0, 0, 0))
    Place(vane_a, position=(0, acrylic / 2, ply), face="front", up="up")
    Place(vane_b, position=(-acrylic / 2, 0, ply), face="right", up="up")
    Place(cap, position=(0, 0, ply + vane_h))

    # the sheet
    RightOf(vane_a, lid, gap=8)
    AlignBottom(vane_a, lid)
    RightOf(vane_b, vane_a, gap=8)
    AlignBottom(vane_b, lid)
    RightOf(cap, vane_b, gap=8)
    AlignBottom(cap, lid)

    # the request's numbers
    assert lid.disc.diameter == 340 mm and lid.funnel.c.diameter == 70 mm, "lid"
    assert cap.disc.diameter == 240 mm and cap.lampholder.c.diameter == 40 mm, "cap"
    assert vane_a.body.bb.width == 220 mm and vane_a.body.bb.height - 2 * ply == 250 mm,
        "vanes 220 x 250 between the tenons' roots"
    assert vane_a.bulb.n.width == 70 mm, "70 wide notch"
    assert vane_a.bulb.n.bb.bottom - (vane_a.body.bb.bottom + ply) == crossing,
        "notch 120 deep from the head"
    assert vane_a.halving.depth + vane_b.halving.depth == crossing, "halvings meet"
    assert notch_w - 60 mm >= 10 mm, "room round a 60 mm bulb"
    assert vane_a.head.gap[1].bb.width >= notch_w + 10 mm, "notch between the head tenons"
    assert distance(lid.mortise_a.slot[0], lid.funnel.c) >= 3 mm and
        distance(lid.mortise_b.slot[1], lid.funnel.c) >= 3 mm, "mortises clear of the hole"
    assert distance(cap.mortise_a.slot[0], cap.lampholder.c) >= 3 mm, "cap mortises clear"
    assert len(vane_a.foot.gap) == 3, "two tenons a foot"
}
