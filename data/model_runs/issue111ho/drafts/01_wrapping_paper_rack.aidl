# Request (home): a free-standing rack that keeps wrapping-paper rolls upright, cut from
# 6 mm birch ply. A base 340 x 200 mm and a top plate 340 x 200 mm with six 80 mm round
# holes (2 rows x 3, 95 mm pitch both ways, centred) for rolls up to 75 mm across. Two side
# panels 200 mm wide and 450 mm tall overall join them with glued tabs (two 20 mm tabs on
# each end, through slots in base and top), standing 157 mm either side of the centre, so
# the top plate sits 438 mm above the base. Each side has a 100 x 30 mm hand hole 60 mm
# below its top and "GIFT WRAP" engraved filled, 16 mm letters, under it.

units mm
thickness 6 mm

import "std/joints.aidl"

# FIX after the first valid program: the unused param `t` (W0115) removed
side_x = 157 mm

def side_panel() -> solid {
    body = Rectangle(center=(0, 225), width=200, height=450)
    foot = tab_and_slot(part="tab", length=200 mm, thickness=6 mm, tabs=2, tab=20 mm,
                        screw=0, rotation=180 deg, cx=0 mm, cy=0 mm)
    head = tab_and_slot(part="tab", length=200 mm, thickness=6 mm, tabs=2, tab=20 mm,
                        screw=0, rotation=0 deg, cx=0 mm, cy=450 mm)
    hole grip {
        s = Slot(center=(0, 390), length=100, width=30)
    }
    drawing label {
        word = Text("GIFT WRAP", (0, 330), size=16, font="sans:Bold", fill=true,
                    valign="middle")
    }
    assert body.bb.top - grip.s.center.y == 60 mm, "hand hole 60 mm below the top"
    assert distance(label, grip) >= 5 mm, "label clear of the hand hole"
}

assembly rack {
    solid base {
        plate = Rectangle(center=(0, 0), width=340, height=200)
        sl = tab_and_slot(part="slot", length=200 mm, thickness=6 mm, tabs=2, tab=20 mm,
                          screw=0, rotation=90 deg, cx=-side_x, cy=0 mm)
        sr = tab_and_slot(part="slot", length=200 mm, thickness=6 mm, tabs=2, tab=20 mm,
                          screw=0, rotation=90 deg, cx=side_x, cy=0 mm)
    }
    solid top {
        plate = Rectangle(center=(0, 0), width=340, height=200)
        hole roll {
            c = Circle(center=(-95, -47.5), diameter=80)
        }
        rolls = GridPattern(roll, 2, 3, spacing=(95, 95))
        sl = tab_and_slot(part="slot", length=200 mm, thickness=6 mm, tabs=2, tab=20 mm,
                          screw=0, rotation=90 deg, cx=-side_x, cy=0 mm)
        sr = tab_and_slot(part="slot", length=200 mm, thickness=6 mm, tabs=2, tab=20 mm,
                          screw=0, rotation=90 deg, cx=side_x, cy=0 mm)
    }
    left = side_panel()
    right = side_panel()

    # flat on the sheet: base, top, then the two sides in a row
    RightOf(top, base, gap=10)
    AlignBottom(top, base)
    RightOf(left, top, gap=10)
    AlignBottom(left, base)
    RightOf(right, left, gap=10)
    AlignBottom(right, base)

    # in 3D: base on the floor, top plate 438 mm above the base, sides standing on their tabs
    Place(base, position=(0, 0, 0))
    Place(top, position=(0, 0, 444))
    Place(left, position=(-side_x + 3, 0, 0), face="left", up="up")
    Place(right, position=(side_x - 3, 0, 0), face="right", up="up")

    assert len(top.rolls) == 6, "six roll holes"
    assert top.roll.c.diameter == 80 mm, "80 mm holes"
    assert top.roll.c.diameter > 75 mm, "a 75 mm roll passes"
    assert top.rolls[1].c.center.x - top.rolls[0].c.center.x == 95 mm, "95 mm pitch across"
    assert top.rolls[3].c.center.y - top.rolls[0].c.center.y == 95 mm, "95 mm pitch back to front"
    assert top.plate.bb.width == 340 mm and top.plate.bb.height == 200 mm, "top 340 x 200"
    assert left.body.bb.height - 2 * 6 mm == 438 mm, "top plate 438 mm above the base"
    assert distance(top.rolls, top.sl) >= 5 mm, "holes clear of the left slots"
    assert distance(top.rolls, top.sr) >= 5 mm, "holes clear of the right slots"
}
