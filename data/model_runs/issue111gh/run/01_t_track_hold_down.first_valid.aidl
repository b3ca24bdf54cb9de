# Request: a hold-down clamp for the 19 mm T-track on my router table, with a 1/4" (M6) T-bolt.
# 6 mm birch ply. The arm is 160 x 36 mm with R8 corners and a 6.5 mm wide, 80 mm long slot
# down its middle that starts 30 mm from the nose end. Under the back end (flush with it) a
# heel of two glued 30 x 36 layers (12 mm), so it holds 12 mm stock flat. A five-point star
# knob 50 mm across (outer radius 25, inner radius 17, tips rounded R5) of two layers: the top
# one with a 6.5 mm hole, the bottom one with a hex pocket for an M6 nut (10 mm across flats,
# plus 0.2 clearance). Engrave "12 MM" on the heel end of the arm and an arrow at the nose.

import "std/fasteners.aidl"

thickness 6 mm

def heel_layer() -> solid {
    r = Rectangle(center=(0, 0), width=30, height=36)
}

def knob_shape(bolt=true) -> solid {
    s = Star(center=(0, 0), points=5, outer_radius=25, inner_radius=17, tip_radius=5)
    if bolt {
        hole bore { c = Circle(center=(0, 0), diameter=6.5) }
    } else {
        nut = nut_trap(size=6, clearance=0.2)
    }
}

assembly hold_down {
    solid arm {
        body = RoundedRectangle(bottom_left=(0, -18), width=160, height=36, corner_radius=8)
        hole slot { s = Slot(start=(33.25, 0), end=(106.75, 0), width=6.5) }
        drawing marks {
            size_label = Text("12 MM", position=(140, 0), size=6, valign="middle")
            arrow = Triangle(center=(15, 0), base=12, height=10, rotation=90)
        }
    }
    heel_a = heel_layer()
    heel_b = heel_layer()
    knob_top = knob_shape(bolt=true)
    knob_nut = knob_shape(bolt=false)

    # flat on the sheet: heels under the arm, knob layers to the right
    Below(heel_a, arm, gap=5)
    AlignLeft(heel_a, arm)
    RightOf(heel_b, heel_a, gap=5)
    AlignTop(heel_b, heel_a)
    RightOf(knob_top, arm, gap=5)
    AlignTop(knob_top, arm)
    RightOf(knob_nut, knob_top, gap=5)
    AlignTop(knob_nut, knob_top)

    # in 3D: heels stacked under the back end, arm on them, knob over the slot
    Place(heel_a, position=(145, 0, 0))
    Place(heel_b, position=(145, 0, 6))
    Place(arm, position=(0, 0, 12))
    Place(knob_nut, position=(70, 0, 18))
    Place(knob_top, position=(70, 0, 24))

    assert arm.body.bb.width == 160 mm, "arm 160 long"
    assert arm.body.bb.height == 36 mm, "arm 36 wide"
    assert arm.slot.s.length == 80 mm, "slot 80 long"
    assert arm.slot.s.width == 6.5 mm, "slot 6.5 wide"
    assert arm.slot.s.bb.left - arm.body.bb.left == 30 mm, "slot starts 30 from the nose"
    assert abs(arm.slot.s.center.y - arm.body.center.y) < 0.01 mm, "slot down the middle"
    assert heel_a.r.width == 30 mm and heel_a.r.height == 36 mm, "heel 30 x 36"
    assert 2 * 6 mm == 12 mm, "two heel layers make 12 mm"
    assert knob_top.s.outer_radius * 2 == 50 mm, "knob 50 across"
    assert knob_nut.nut.hex.across_flats == 10.2 mm, "M6 nut 10 + 0.2"
    assert knob_top.bore.c.diameter == 6.5 mm, "bolt hole 6.5"
}
