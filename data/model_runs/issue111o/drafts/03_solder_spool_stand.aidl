# Electronics: a solder-spool stand from two cross-halved plates, 3 mm plywood.
# Each plate is an inverted T, 120 mm tall: a foot 100 x 20 mm and a spindle 12 mm wide
# rising 100 mm from the foot's middle; the two inner corners where spindle meets foot
# rounded R4. The plates cross at right angles: plate A has a cross-halving slot 60 mm deep
# from the spindle's top, plate B one 60 mm deep from the foot's bottom (the two add up to
# the 120 mm height), 3 mm + 0.1 mm clearance. The spool (bore >= 18 mm) drops over the
# crossed spindle. Plate A's foot has "SOLDER" engraved 6 mm tall in its left wing.

import "std/joints.aidl"

thickness 3 mm

def upright(mouth_y=120 mm, turn=0 deg) -> solid {
    foot = Rectangle(center=(0, 10), width=100, height=20)
    spindle = Rectangle(center=(0, 70), width=12, height=100)
    slot = cross_halving(depth=60 mm, thickness=3 mm, clearance=0.1 mm, rotation=turn,
                         cx=0 mm, cy=mouth_y)
    Fillet([spindle.bottom_left, spindle.bottom_right], 4)
}

assembly stand {
    a = upright(mouth_y=120 mm, turn=0 deg)
    b = upright(mouth_y=0 mm, turn=180 deg)
    RightOf(b, a, gap=10)
    AlignBottom(b, a)

    drawing label {
        word = Text("SOLDER", (-28, 10), size=6, valign="middle")
    }
    # centred in plate A's left wing (between the foot's left end and the spindle)
    label.word.position.x == (a.foot.bb.left + a.spindle.bb.left) / 2
    label.word.position.y == a.foot.bb.center_y
    CutInto(label, a)

    assert a.foot.width == 100 mm and a.foot.height == 20 mm, "foot 100 x 20"
    assert a.spindle.width == 12 mm, "spindle 12 mm wide"
    assert a.bb.height == 120 mm and b.bb.height == 120 mm, "plates 120 mm tall"
    assert a.spindle.bb.top - a.foot.bb.top == 100 mm, "spindle rises 100 mm"
    assert a.slot.cut.bb.height == 60 mm, "A: 60 mm deep"
    assert b.slot.cut.bb.height == 60 mm, "B: 60 mm deep"
    assert a.slot.cut.bb.width == 3.1 mm, "3 mm + 0.1 clearance"
    assert a.slot.cut.bb.top == a.spindle.bb.top, "A's slot from the spindle's top"
    assert b.slot.cut.bb.bottom == b.foot.bb.bottom, "B's slot from the foot's bottom"
    assert a.slot.cut.bb.height + b.slot.cut.bb.height == 120 mm, "depths add up"
    assert label.word.size == 6 mm, "6 mm text"
    assert label.bb.left > a.foot.bb.left + 2 mm, "text on the foot"
    assert label.bb.right < a.spindle.bb.left - 2 mm, "text clear of the spindle"
}
