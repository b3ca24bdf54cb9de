# Request (garden): a butterfly feeder on a stake, 6 mm exterior plywood.
# Flower plate: a 70 mm centre disc with 8 round petals (30 mm across, centres on a 46 mm
# radius), so 122 mm across; a 44 mm ring engraved in the centre where the sugar-water sponge
# sits; a 6 mm drain hole in the middle of 7 petals; the 8th petal holds a butterfly.
# Stake: 600 mm long, 30 mm wide, pointed (last 60 mm) to push into the lawn; two 8 mm tabs on
# its top glued into the plate. Under the plate a trapezoid gusset (80 mm at the top, 30 mm at
# the bottom, 46 mm tall with its tabs) crosses the stake by a cross-halving and is glued into
# the plate by two 10 mm tabs. Butterfly: about 70 mm wingspan, standing on the 8th petal by a
# 10 mm tab, two engraved spots on its upper wings, antennae with round tips.

import "std/joints.aidl"

thickness 6 mm

param t = 6 mm, min = 4 mm, max = 9 mm
param petals = 8, min = 6, max = 10
param stake_len = 600 mm, min = 400 mm, max = 900 mm

assembly butterfly_feeder {
    solid plate {
        disc = Circle(center=(0, 0), diameter=70)
        petal = Circle(center=(46, 0), diameter=30)
        ring = CircularPattern(petal, petals, (0, 0))
        hole drain { c = Circle(center=(46 * cos(45 deg), 46 * sin(45 deg)), diameter=6) }
        drains = CircularPattern(drain, petals - 1, (0, 0), step=360 deg / petals)
        stake_slots = tab_and_slot(part="slot", length=30 mm, thickness=t, tabs=2, tab=8 mm,
                                   screw=0, cx=0 mm, cy=0 mm)
        gusset_slots = tab_and_slot(part="slot", length=80 mm, thickness=t, tabs=2, tab=10 mm,
                                    screw=0, rotation=90 deg, cx=0 mm, cy=0 mm)
        butterfly_slot = tab_and_slot(part="slot", length=20 mm, thickness=t, tabs=1, tab=10 mm,
                                      screw=0, rotation=90 deg, cx=46 mm, cy=0 mm)
        drawing seat { c = Circle(center=(0, 0), diameter=44) }
    }

    solid stake {
        body = Rectangle(center=(0, -(stake_len - 60) / 2), width=30, height=stake_len - 60)
        point = Polygon([(-15, -(stake_len - 60)), (15, -(stake_len - 60)), (0, -stake_len)])
        top = tab_and_slot(part="tab", length=30 mm, thickness=t, tabs=2, tab=8 mm, screw=0,
                           cx=0 mm, cy=0 mm)
        halving = cross_halving(depth=20 mm, thickness=t, cx=0 mm, cy=-t)
    }

    solid gusset {
        web = Trapezoid(center=(0, -23), bottom_width=30, top_width=80, height=46)
        top = tab_and_slot(part="tab", length=80 mm, thickness=t, tabs=2, tab=10 mm, screw=0,
                           cx=0 mm, cy=0 mm)
        halving = cross_halving(depth=20 mm, thickness=t, rotation=180 deg, cx=0 mm, cy=-46 mm)
    }

    solid butterfly {
        axis = Line((0, 0), (0, 60), construction=true)
        stand = Rectangle(center=(0, 5), width=20, height=10)
        body = Ellipse(center=(0, 30), rx=3.5, ry=22)
        upper = Spline([(2, 30), (14, 48), (34, 46), (30, 30), (4, 24)], closed=true)
        lower = Spline([(2, 24), (22, 20), (22, 6), (8, 8)], closed=true)
        feeler = Stroke(Line((1, 50), (9, 60)), width=2)
        knob = Circle(center=(9, 60), radius=2.5)
        upper_l = Mirrored(upper, axis)
        lower_l = Mirrored(lower, axis)
        feeler_l = Mirrored(feeler, axis)
        knob_l = Mirrored(knob, axis)
        tab = tab_and_slot(part="tab", length=20 mm, thickness=t, tabs=1, tab=10 mm, screw=0,
                           cx=0 mm, cy=0 mm)
        drawing spots {
            r = Circle(center=(22, 40), radius=4)
            l = Circle(center=(-22, 40), radius=4)
        }
    }

    # flat on the sheet
    RightOf(stake, plate, gap=10)
    AlignTop(stake, plate)
    RightOf(gusset, stake, gap=10)
    AlignTop(gusset, plate)
    Below(butterfly, plate, gap=10)
    AlignLeft(butterfly, plate)

    # assembled: stake upright (its tip at z = 0), plate on its shoulders, gusset across it,
    # butterfly standing on the 8th petal facing out
    Place(stake, position=(0, t / 2, stake_len), face="front", up="up")
    Place(plate, position=(0, 0, stake_len - t), face="up")
    Place(gusset, position=(-t / 2, 0, stake_len), face="right", up="up")
    Place(butterfly, position=(46 - t / 2, 0, stake_len - t), face="right", up="up")

    # the request's numbers
    assert len(plate.ring) == 8 and len(plate.drains) == 7
    assert plate.disc.diameter == 70 mm and plate.petal.diameter == 30 mm
    assert plate.petal.center.x - plate.disc.center.x == 46 mm
    assert plate.bb.width == 122 mm
    assert plate.seat.c.diameter == 44 mm and plate.drain.c.diameter == 6 mm
    assert stake.bb.height == 600 mm and stake.body.width == 30 mm
    assert stake.body.bb.bottom - stake.point.bb.bottom == 60 mm
    assert gusset.web.top_width == 80 mm and gusset.web.bottom_width == 30 mm
    assert gusset.bb.height == 46 mm
    assert butterfly.bb.width >= 60 mm and butterfly.bb.width <= 80 mm
    # the halvings' depths add up to the gusset's height below the plate
    assert stake.halving.depth + gusset.halving.depth == 46 mm - t
    # the stake's halving falls in the gap between its two tabs
    assert stake.halving.cut.bb.left >= stake.top.gap[1].bb.left
    assert stake.halving.cut.bb.right <= stake.top.gap[1].bb.right
}
