# Request (home, living room): a stand for two game controllers, one above the other, in 6 mm
# plywood. A base 180 x 120 with R10 front corners. A back plate 180 wide standing 230 mm
# above the base, R25 top corners, glued into the base by three 20 mm tenons whose mortises
# sit 8 mm in from the base's back edge. Two cradles 100 wide standing 70 mm out of the back
# plate's front face, their top faces 70 mm and 180 mm above the base; each cradle has a
# round-ended notch 44 wide and 45 deep open at its front (the controller's middle drops in,
# the grips hang either side) and R8 front corners, and is glued into the back plate by two
# 15 mm tenons. "P1" and "P2" engraved filled, 12 mm tall, to the left of each cradle.

import "std/joints.aidl"

thickness 6 mm
t = 6 mm

base_w = 180 mm
base_d = 120 mm
back_h = 230 mm
cradle_w = 100 mm
cradle_d = 70 mm
lower_top = 70 mm
upper_top = 180 mm
notch_w = 44 mm
notch_d = 45 mm

def cradle() -> solid {
    # frame: the shoulder (back plate's front face) on y = 0, the cradle toward -y
    plate = RoundedRectangle(bottom_left=(-cradle_w / 2, -cradle_d), width=cradle_w,
                             height=cradle_d + t, corner_radii=[0, 0, 8, 8])
    tenons = tab_and_slot(part="tab", length=cradle_w, thickness=t, tabs=2, tab=15 mm,
                          screw=0, cx=0 mm, cy=t)
    hole notch {
        end = Circle(center=(0, -cradle_d + notch_d - notch_w / 2), radius=notch_w / 2)
        mouth = Rectangle(bottom_left=(-notch_w / 2, -cradle_d - 1), width=notch_w,
                          height=notch_d - notch_w / 2 + 1)
    }
}

assembly controller_stand {
    solid base {
        plate = RoundedRectangle(center=(0, 0), width=base_w, height=base_d,
                                 corner_radii=[0, 0, 10, 10])
        # the back plate's middle stands 8 mm + t / 2 in from the back edge
        mort = tab_and_slot(part="slot", length=base_w, thickness=t, tabs=3, tab=20 mm,
                            screw=0, cx=0 mm, cy=base_d / 2 - 8 mm - t / 2)
    }

    solid back {
        # frame: y = 0 is the base's top face (the tenons' shoulder), the tips at y = -t
        body = RoundedRectangle(bottom_left=(-base_w / 2, -t), width=base_w, height=back_h + t,
                                corner_radii=[25, 25, 0, 0])
        tenons = tab_and_slot(part="tab", length=base_w, thickness=t, tabs=3, tab=20 mm,
                              screw=0, rotation=180 deg, cx=0 mm, cy=-t)
        lo = tab_and_slot(part="slot", length=cradle_w, thickness=t, tabs=2, tab=15 mm,
                          screw=0, cx=0 mm, cy=lower_top - t / 2)
        hi = tab_and_slot(part="slot", length=cradle_w, thickness=t, tabs=2, tab=15 mm,
                          screw=0, cx=0 mm, cy=upper_top - t / 2)
        drawing p1 {
            l = Text("P1", position=(-(base_w + cradle_w) / 4, lower_top + 14 mm), size=12,
                     font="sans:Bold", valign="middle", fill=true)
        }
        drawing p2 {
            l = Text("P2", position=(-(base_w + cradle_w) / 4, upper_top + 14 mm), size=12,
                     font="sans:Bold", valign="middle", fill=true)
        }
    }

    lower = cradle()
    upper = cradle()

    # flat on the sheet: base right of the back, the cradles right of the base
    RightOf(base, back, gap=10)
    AlignBottom(base, back)
    RightOf(lower, base, gap=10)
    AlignBottom(lower, base)
    Above(upper, lower, gap=10)
    AlignLeft(upper, lower)

    # in 3D
    Place(base, position=(0, 0, 0))
    Place(back, position=(0, base_d / 2 - 8 mm, t), face="front", up="up")
    Place(lower, position=(0, base_d / 2 - 8 mm - t, t + lower_top - t))
    Place(upper, position=(0, base_d / 2 - 8 mm - t, t + upper_top - t))

    assert base.plate.bb.width == 180 mm and base.plate.bb.height == 120 mm, "base 180 x 120"
    assert back.body.bb.height - 6 mm == 230 mm, "back stands 230 above the base"
    assert back.body.bb.width == 180 mm, "back 180 wide"
    assert back.lo.slot[0].bb.top - (back.body.bb.bottom + 6 mm) == 70 mm, "lower cradle top 70 up"
    assert back.hi.slot[0].bb.top - (back.body.bb.bottom + 6 mm) == 180 mm, "upper cradle top 180 up"
    assert base.plate.bb.top - base.mort.slot[0].bb.top == 8 mm, "mortises 8 mm in from the back"
    assert len(base.mort.slot) == 3 and len(back.lo.slot) == 2, "3 base tenons, 2 per cradle"
    assert lower.plate.bb.width == 100 mm, "cradle 100 wide"
    assert lower.plate.bb.height - 6 mm == 70 mm, "cradle stands 70 out"
    assert lower.notch.bb.width == 44 mm, "notch 44 wide"
    assert lower.notch.bb.top - (lower.plate.bb.bottom) == 45 mm, "notch 45 deep"
}
