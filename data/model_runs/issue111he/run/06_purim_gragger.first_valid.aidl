# Request (holidays): a Purim gragger (ratchet noisemaker) in 6 mm plywood, on a bought 8 mm
# dowel handle. A 12-tooth gear, module 4 mm, is glued on the dowel (8 mm bore). Two arms
# 30 mm wide turn freely on the dowel (8.6 mm holes), one above and one below the gear, and
# are bolted together at their far end through the root of a springy tongue with two M4
# bolts (4.5 mm holes, 14 mm apart, centred 100 mm from the dowel). The tongue lies in the
# gear's plane: a 30 x 30 mm root and a strip 4 mm wide that reaches 4 mm into the gear's
# teeth so it snaps from tooth to tooth. The top arm is engraved with a Star of David
# (two triangles, 9 mm radius) and PURIM in filled bold letters 9 mm tall.

import "std/gears.aidl"

thickness 6 mm

teeth = 12
gear_module = 4 mm
bite = 4 mm
bolt_x = 100 mm

def arm(engraved=false) -> solid {
    pivot = Circle(center=(0, 0), radius=15)
    tail = Circle(center=(105, 0), radius=15)
    body = Hull(pivot, tail)
    hole axle { c = Circle(center=(0, 0), diameter=8.6) }
    hole bolts {
        b1 = Circle(center=(bolt_x - 7 mm, 0), diameter=4.5)
        b2 = Circle(center=(bolt_x + 7 mm, 0), diameter=4.5)
    }
    if engraved {
        drawing star {
            up = RegularPolygon(center=(28, 0), radius=9, sides=3, rotation=90)
            down = RegularPolygon(center=(28, 0), radius=9, sides=3, rotation=270)
        }
        drawing word {
            t = Text("PURIM", position=(62, 0), size=9, font="sans:Bold", valign="middle",
                     fill=true)
        }
    }
}

assembly gragger {
    gear = spur_gear(teeth=teeth, module=gear_module, bore=8 mm)
    top_arm = arm(engraved=true)
    bottom_arm = arm(engraved=false)

    solid tongue {
        axle = Circle(center=(0, 0), diameter=8, construction=true)
        root = Rectangle(center=(bolt_x, 0), width=30, height=30)
        strip = Rectangle(center=((gear_module * (teeth + 2) / 2 - bite + bolt_x - 15 mm) / 2, 0),
                          width=bolt_x - 15 mm - (gear_module * (teeth + 2) / 2 - bite),
                          height=4)
        hole bolts {
            b1 = Circle(center=(bolt_x - 7 mm, 0), diameter=4.5)
            b2 = Circle(center=(bolt_x + 7 mm, 0), diameter=4.5)
        }
        Fillet([strip, root], 3)
    }

    assert gear.tip.diameter == 56 mm, "module 4 x (12 + 2)"
    assert gear.tip.radius - (tongue.strip.bb.left - tongue.axle.center.x) == 4 mm,
        "tongue bites 4 mm into the teeth"
    assert tongue.strip.bb.height == 4 mm, "4 mm strip"
    assert top_arm.bolts.b2.center.x - top_arm.bolts.b1.center.x == 14 mm, "bolts 14 apart"
    assert ((top_arm.bolts.b1.center.x + top_arm.bolts.b2.center.x) / 2
        - top_arm.axle.c.center.x == 100 mm), "bolts 100 from the dowel"
    assert distance(top_arm.word, top_arm.bolts) >= 3 mm, "word clear of the bolts"
    assert distance(top_arm.star, top_arm.axle) >= 3 mm, "star clear of the dowel"

    RightOf(top_arm, gear, gap=10)
    AlignTop(top_arm, gear)
    Below(bottom_arm, top_arm, gap=8)
    AlignLeft(bottom_arm, top_arm)
    Below(tongue, bottom_arm, gap=8)
    AlignLeft(tongue, bottom_arm)
}
