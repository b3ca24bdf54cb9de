# Request (electronics, gaming): a desk stand for a VR headset and its two controllers,
# 6 mm birch ply, three parts.
# - Two uprights that cross at right angles in a cross halving: one slotted 165 mm down from
#   its top, the other 165 mm up from its bottom, slots 0.2 mm over the 6 mm ply.
# - Each upright: a stem 70 mm wide, 330 mm tall overall (tab tips to the top of the head),
#   ending in a rounded "head" 150 mm wide and 120 mm tall with 55 mm corner radii, which the
#   headset's face opening sits over. Its bottom edge has two glued 20 mm tabs, 6 mm long.
# - The front upright also has two arms, 20 mm tall, their bottom 170 mm above the tab tips,
#   250 mm across overall, each ending in a 10 mm wide lip that stands 20 mm above the arm:
#   the controllers hang on them by their wrist straps.
# - A round base 240 mm across with a pair of slots for each upright's tabs (0.2 mm over),
#   four countersunk M4 holes (4.5 mm through, 9 mm countersink) on a 180 mm circle at
#   45, 135, 225 and 315 deg to screw it to a shelf, and the owner's name "ALEX" engraved
#   filled, 12 mm tall, bold, centred 80 mm in front of the centre.
# For the assembled view: the base flat, the front upright facing front, the other facing
# right, both centred on the base's slots.

import "std/joints.aidl"

units mm
thickness 6 mm

def upright(arms=false, from_top=true) -> solid {
    stem = Rectangle(bottom_left=(-35, 0), width=70, height=230)
    head = RoundedRectangle(center=(0, 270), width=150, height=120, corner_radius=55)
    if arms {
        arm = Rectangle(bottom_left=(-125, 170), width=250, height=20)
        lip_left = Rectangle(bottom_left=(-125, 170), width=10, height=40)
        lip_right = Rectangle(bottom_left=(115, 170), width=10, height=40)
    }
    feet = tab_and_slot(part="tab", length=70 mm, thickness=6 mm, tabs=2, tab=20 mm, screw=0,
                        rotation=180 deg, cx=0 mm, cy=0 mm)
    if from_top {
        halving = cross_halving(depth=165 mm, thickness=6 mm, clearance=0.2 mm, cx=0 mm, cy=330 mm)
    } else {
        halving = cross_halving(depth=165 mm, thickness=6 mm, clearance=0.2 mm,
                                rotation=180 deg, cx=0 mm, cy=0 mm)
    }
}

assembly vr_stand {
    front = upright(arms=true, from_top=false)
    side = upright(arms=false, from_top=true)

    solid base {
        disc = Circle(center=(0, 0), diameter=240)
        front_slots = tab_and_slot(part="slot", length=70 mm, thickness=6 mm, tabs=2, tab=20 mm,
                                   screw=0, clearance=0.2 mm, cx=0 mm, cy=0 mm)
        side_slots = tab_and_slot(part="slot", length=70 mm, thickness=6 mm, tabs=2, tab=20 mm,
                                  screw=0, clearance=0.2 mm, rotation=90 deg, cx=0 mm, cy=0 mm)
        hole fix {
            for i in range(4) {
                c = Circle(center=polar((0, 0), 90, 45 deg + i * 90 deg), diameter=4.5)
            }
        }
        Countersink(fix, diameter=9 mm)
        drawing name {
            t = Text("ALEX", position=(0, -80), size=12, font="sans:Bold", valign="middle", fill=true)
        }
    }

    # laid out flat for cutting
    RightOf(side, front, gap=10)
    AlignBottom(side, front)
    RightOf(base, side, gap=10)
    AlignBottom(base, side)

    # assembled
    Place(base, position=(0, 0, 0))
    Place(front, position=(0, 3, 0), face="front", up="up")
    Place(side, position=(-3, 0, 0), face="right", up="up")

    # the request's numbers
    assert front.stem.width == 70 mm and side.stem.width == 70 mm, "stems 70 wide"
    assert front.head.bb.top - front.stem.bb.bottom == 330 mm, "330 tall overall"
    assert side.head.bb.top - side.stem.bb.bottom == 330 mm, "330 tall overall"
    assert front.head.width == 150 mm and front.head.height == 120 mm, "head 150 x 120"
    assert front.arm.bb.bottom - front.stem.bb.bottom == 170 mm, "arms 170 up"
    assert front.arm.width == 250 mm and front.arm.height == 20 mm, "arms 250 across, 20 tall"
    assert front.lip_left.bb.top - front.arm.bb.top == 20 mm, "lip 20 above the arm"
    assert front.lip_right.bb.top - front.arm.bb.top == 20 mm, "lip 20 above the arm"
    assert front.halving.cut.bb.height == 165 mm and side.halving.cut.bb.height == 165 mm, "halvings 165"
    assert front.halving.cut.bb.bottom == front.stem.bb.bottom, "front upright slotted from its bottom"
    assert side.halving.cut.bb.top == side.head.bb.top, "side upright slotted from its top"
    assert abs(front.halving.cut.bb.width - 6.2 mm) < 0.001 mm, "halving 0.2 over the ply"
    assert len(front.feet.gap) == 3 and len(base.front_slots.slot) == 2 and len(base.side_slots.slot) == 2, "two tabs each"
    assert base.disc.diameter == 240 mm, "base 240"
    assert len(base.fix.c) == 4, "four screws"
    for i in range(4) {
        assert abs(distance(base.fix.c[i].center, base.disc.center) - 90 mm) < 0.001 mm, "on a 180 circle"
    }
    assert base.disc.center.y - base.name.t.position.y == 80 mm, "name 80 in front of the centre"
    assert distance(base.name, base.fix) >= 2 mm, "name clear of the screws"
}
