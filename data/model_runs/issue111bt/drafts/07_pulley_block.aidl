# Request: a single-sheave pulley block for the physics class (to hang from a hook and lift
# weights with 6 mm cord), all 6 mm plywood, five parts bolted on an M8 axle. The sheave is
# laminated from three discs: two 60 mm flanges and a 50 mm core between them, so the cord runs
# in a 6 mm wide, 5 mm deep groove; each has an 8.2 mm axle hole, and each flange carries twelve
# engraved radial marks (from 20 to 27 mm out) so the class can count its turns. Two cheeks hold
# the axle: each the hull of a 70 mm circle round the axle, a 30 mm boss 60 mm above it with a
# 12 mm hole for the hook, and a 24 mm boss 45 mm below it with an 8 mm becket hole for a dead
# end; the front cheek engraved "SINGLE PULLEY" (6 mm) and the back one "MA = 1", each on its
# outside face, below the axle hole.

units mm
thickness 6 mm
import "std/shapes.aidl"

AXLE = 8.2 mm
FLANGE_D = 60 mm
CORE_D = 50 mm
HOOK_UP = 60 mm
BECKET_DOWN = 45 mm

def flange() -> solid {
    disc = Circle(center=(0, 0), diameter=FLANGE_D)
    hole axle { c = Circle(center=(0, 0), diameter=AXLE) }
    drawing ticks {
        for k in range(12) {
            m = Line(start=(20 mm * cos(k * 30 deg), 20 mm * sin(k * 30 deg)),
                     end=(27 mm * cos(k * 30 deg), 27 mm * sin(k * 30 deg)))
        }
    }
}

def cheek(line1="MA = 1", line2="") -> solid {
    round = Circle(center=(0, 0), diameter=70)
    top = Circle(center=(0, HOOK_UP), diameter=30)
    bottom = Circle(center=(0, -BECKET_DOWN), diameter=24)
    body = Hull(round, top, bottom)
    hole axle { c = Circle(center=(0, 0), diameter=AXLE) }
    hole hook { c = Circle(center=(0, HOOK_UP), diameter=12) }
    hole becket { c = Circle(center=(0, -BECKET_DOWN), diameter=8) }
    # FIX after the first valid program (W0505: "SINGLE PULLEY" ran off the narrow waist): two
    # lines in the wide part below the axle hole, still 6 mm
    drawing name {
        t1 = Text(line1, position=(0, -13), size=6, valign="middle")
        if line2 != "" {
            t2 = Text(line2, position=(0, -23), size=6, valign="middle")
        }
    }
}

assembly block {
    front = cheek(line1="SINGLE", line2="PULLEY")
    flange_a = flange()
    core = washer(outer=CORE_D, inner=AXLE)
    flange_b = flange()
    back = cheek(line1="MA = 1")

    # flat on the sheet, in a row
    RightOf(flange_a, front, gap=8)
    RightOf(core, flange_a, gap=8)
    RightOf(flange_b, core, gap=8)
    RightOf(back, flange_b, gap=8)
    AlignCenterY(flange_a, front.axle)
    AlignCenterY(core, front.axle)
    AlignCenterY(flange_b, front.axle)
    AlignCenterY(back.axle, front.axle)

    # stacked on the axle (z up through the stack); the front cheek turned over so that its
    # engraving faces out (down), the back cheek's faces up
    # FIX after the first valid program: turned over about x, the front cheek had its hook
    # where the back one has its becket; turned over about y (the cheek's own axis) instead
    Place(front, rotation=(0, 180 deg, 0), position=(0, 0, 6))
    Place(flange_a, position=(0, 0, 6))
    Place(core, position=(0, 0, 12))
    Place(flange_b, position=(0, 0, 18))
    Place(back, position=(0, 0, 24))

    assert flange_a.disc.diameter == 60 mm and core.ring.diameter == 50 mm, "60 / 50 mm discs"
    assert (flange_a.disc.diameter - core.ring.diameter) / 2 == 5 mm, "5 mm deep groove"
    assert flange_a.axle.c.diameter == 8.2 mm and core.bore.b.diameter == 8.2 mm and
        front.axle.c.diameter == 8.2 mm, "8.2 mm axle holes"
    assert len(flange_a.ticks.m) == 12, "twelve marks"
    assert front.hook.c.center.y - front.axle.c.center.y == 60 mm, "hook 60 mm above the axle"
    assert front.axle.c.center.y - front.becket.c.center.y == 45 mm, "becket 45 mm below"
    assert front.hook.c.diameter == 12 mm and front.becket.c.diameter == 8 mm, "hook, becket"
    # the hook's and the becket's bolts must clear the sheave and the cord on it (6 mm)
    assert front.hook.c.center.y - front.axle.c.center.y - 6 mm >= FLANGE_D / 2 + 6 mm,
        "hook bolt clears the sheave"
    assert front.axle.c.center.y - front.becket.c.center.y - 4 mm >= FLANGE_D / 2 + 6 mm,
        "becket bolt clears the sheave"
}
