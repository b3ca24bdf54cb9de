# Request (science): a syringe-powered hydraulic arm for a science class, from 4 mm plywood.
# A 120 x 160 mm base with a 4.5 mm screw hole 10 mm in from each corner (to clamp it to a
# desk). Two 60 mm wide uprights stand on it (two glued 12 mm tabs each) with a 6.2 mm pivot
# hole 104 mm above the base's underside, their tops rounded around the pivot (12 mm radius).
# A 24 mm wide boom, 190 mm between its end holes, swings between the uprights on a 6 mm dowel
# with 0.6 mm play each side; a 4.2 mm hole 80 mm from the pivot takes the pin of the working
# syringe's plunger and a 6 mm hole at the tip hangs a hook. A 30 mm wide syringe bracket
# (one 14 mm tab) stands on the base 80 mm in front of the pivot with a 4.2 mm pin hole 19 mm
# above the base's underside, so a 10 ml syringe (85 mm pin to pin) lifts the boom. Show it
# assembled.

import "std/joints.aidl"

thickness 4 mm

param play = 0.6 mm, min = 0.2 mm, max = 1.5 mm
param pivot_h = 104 mm, min = 80 mm, max = 140 mm

upright_x = 2 mm + play + 2 mm       # the uprights' middle planes, each side of the boom

def upright() -> solid {
    body = Hull(Rectangle(center=(0, 30), width=60, height=60),
                Circle(center=(0, pivot_h), radius=12))
    hole pivot { c = Circle(center=(0, pivot_h), diameter=6.2) }
    feet = tab_and_slot(part="tab", length=60 mm, thickness=4 mm, tabs=2, tab=12 mm,
                        screw=0, rotation=180 deg, cx=0 mm, cy=0 mm)
}

assembly arm {
    solid base {
        plate = Rectangle(center=(0, 25), width=120, height=160)
        hole screw { c = Circle(center=(0, 0), diameter=4.5) }
        screws = CornerPattern(screw, plate, inset=10)
        s_left = tab_and_slot(part="slot", length=60 mm, thickness=4 mm, tabs=2, tab=12 mm,
                              screw=0, rotation=90 deg, cx=-upright_x, cy=0 mm)
        s_right = tab_and_slot(part="slot", length=60 mm, thickness=4 mm, tabs=2, tab=12 mm,
                               screw=0, rotation=90 deg, cx=upright_x, cy=0 mm)
        s_bracket = tab_and_slot(part="slot", length=30 mm, thickness=4 mm, tabs=1, tab=14 mm,
                                 screw=0, rotation=90 deg, cx=0 mm, cy=80 mm)
    }

    left = upright()
    right = upright()

    solid boom {
        bar = Slot(start=(0, 0), end=(190, 0), width=24)
        hole pivot { c = Circle(center=(0, 0), diameter=6.2) }
        hole pin { c = Circle(center=(80, 0), diameter=4.2) }
        hole hook { c = Circle(center=(190, 0), diameter=6) }
        hole lighten {
            a = Slot(start=(18, 0), end=(62, 0), width=10)
            b = Slot(start=(98, 0), end=(172, 0), width=10)
        }
    }

    solid bracket {
        body = Hull(Rectangle(center=(0, 6), width=30, height=12), Circle(center=(0, 19), radius=8))
        hole pin { c = Circle(center=(0, 19), diameter=4.2) }
        foot = tab_and_slot(part="tab", length=30 mm, thickness=4 mm, tabs=1, tab=14 mm,
                            screw=0, rotation=180 deg, cx=0 mm, cy=0 mm)
    }

    # on the sheet
    RightOf(left, base, gap=8)
    RightOf(right, left, gap=8)
    AlignBottom(left, base)
    AlignBottom(right, base)
    Above(boom, base, gap=8)
    AlignLeft(boom, base)
    RightOf(bracket, right, gap=8)
    AlignBottom(bracket, base)

    # assembled
    Place(base, position=(0, 0, 0))
    Place(left, position=(-upright_x + 2 mm, 0, 0), face="left", up="up")
    Place(right, position=(upright_x - 2 mm, 0, 0), face="right", up="up")
    Place(boom, position=(-2 mm, 0, pivot_h), face="right", up="up")
    Place(bracket, position=(-2 mm, 80, 0), face="right", up="up")

    assert base.plate.width == 120 mm and base.plate.height == 160 mm
    assert len(base.screws) == 4
    assert left.pivot.c.center.y - left.feet.bb.bottom == 104 mm, "pivot 104 above the underside"
    assert left.body.bb.width == 60 mm
    assert distance(boom.pivot.c.center, boom.hook.c.center) == 190 mm
    assert distance(boom.pivot.c.center, boom.pin.c.center) == 80 mm
    assert boom.bar.width == 24 mm
    assert bracket.body.bb.width == 30 mm
    assert bracket.pin.c.center.y - bracket.foot.bb.bottom == 19 mm
    assert base.s_bracket.slot[0].bb.center_y - base.s_left.slot[0].bb.center_y >= 0 mm
    assert (pivot_h - 19 mm) == 85 mm, "85 mm syringe pin to pin"
    assert upright_x - 2 mm - 2 mm == 0.6 mm, "0.6 mm play each side of the boom"
}
