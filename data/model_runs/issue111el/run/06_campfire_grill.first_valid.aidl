# Request: a flat-pack campfire grill from 2 mm mild steel (fibre laser), four parts that
# slot together without tools. Grate 380 x 220: sixteen openings 8 x 170 (round ends) on a
# 16 mm pitch, centred; a 70 x 22 hand hole 165 either side of the middle. Two legs, 180
# tall to the tabs' tips, trapezoid 240 at the ground and 200 at the top, an arch R? through
# 60 above the ground and 80 either side of the middle (two feet); each leg stands through
# the grate on two 20 mm tabs, 140 either side of the grate's middle. A brace 320 x 40 links
# the legs just above the arches, cross-halved into them (0.2 mm clearance); BASE CAMP cut
# through it as 16 mm stencil letters.

import "std/joints.aidl"

units mm
thickness 2 mm

t = 2 mm
leg_x = 140 mm
leg_h = 180 mm
arch_top = 60 mm
brace_h = 40 mm
fit = 0.2 mm

def leg() -> solid {
    body = Polygon([(-120, 0), (120, 0), (100, leg_h), (-100, leg_h)])
    hole arch {
        a = Arc(start=(-80, -1), through=(0, arch_top), end=(80, -1))
        l = Line((80, -1), (-80, -1))
    }
    tabs = tab_and_slot(part="tab", length=200 mm, thickness=t, tabs=2, tab=20 mm, screw=0,
                        cx=0 mm, cy=leg_h)
    halving = cross_halving(depth=brace_h / 2, thickness=t, clearance=fit, rotation=180 deg,
                            cx=0 mm, cy=arch_top)
    assert body.bb.height == 180 mm, "180 tall to the tabs' tips"
    assert body.bb.width == 240 mm, "240 at the ground"
}

assembly grill {
    solid grate {
        plate = Rectangle(center=(0, 0), width=380, height=220)
        hole opening { s = Slot(center=(-120, 0), length=170, width=8, rotation=90) }
        openings = LinearPattern(opening, 16, (16, 0))
        hole left_grip { s = Slot(center=(-165, 0), length=70, width=22, rotation=90) }
        hole right_grip { s = Slot(center=(165, 0), length=70, width=22, rotation=90) }
        left_mortise = tab_and_slot(part="slot", length=200 mm, thickness=t, tabs=2, tab=20 mm,
                                    screw=0, clearance=fit, rotation=90 deg, cx=-leg_x, cy=0 mm)
        right_mortise = tab_and_slot(part="slot", length=200 mm, thickness=t, tabs=2, tab=20 mm,
                                     screw=0, clearance=fit, rotation=90 deg, cx=leg_x, cy=0 mm)
        assert len(openings) == 16, "sixteen openings"
        assert openings[15].s.center.x - openings[0].s.center.x == 15 * 16 mm, "16 mm pitch"
        assert openings[0].s.center.x + openings[15].s.center.x == 0 mm, "openings centred"
        assert distance(openings[0], left_mortise) >= 8 mm, "steel between openings and tabs"
        assert distance(left_grip, left_mortise) >= 8 mm, "steel between grip and tabs"
        assert plate.bb.left - left_grip.bb.left <= -10 mm, "a bar outside the hand hole"
    }

    left_leg = leg()
    right_leg = leg()

    solid brace {
        bar = Rectangle(corner=(-160, 0), opposite=(160, brace_h))
        left_halving = cross_halving(depth=brace_h / 2, thickness=t, clearance=fit,
                                     cx=-leg_x, cy=brace_h)
        right_halving = cross_halving(depth=brace_h / 2, thickness=t, clearance=fit,
                                      cx=leg_x, cy=brace_h)
        hole name {
            w = Text("BASE CAMP", position=(0, brace_h / 2), size=16, font="sans:Bold",
                     valign="middle", stencil=true)
        }
        assert distance(name, left_halving) >= 10 mm, "letters clear of the halvings"
        assert name.bb.bottom - bar.bb.bottom >= 5 mm, "steel under the letters"
    }

    # flat on the sheet
    Below(left_leg, grate, gap=5)
    AlignLeft(left_leg, grate)
    RightOf(right_leg, left_leg, gap=5)
    AlignBottom(right_leg, left_leg)
    Below(brace, left_leg, gap=5)
    AlignLeft(brace, left_leg)

    # assembled: legs across the x axis at +-140, the grate on their shoulders, the brace
    # along the middle, its bottom on the arches' tops
    Place(left_leg, position=(-leg_x - t / 2, 0, 0), face="right", up="up")
    Place(right_leg, position=(leg_x - t / 2, 0, 0), face="right", up="up")
    Place(grate, position=(0, 0, leg_h - t), face="up")
    Place(brace, position=(0, t / 2, arch_top), face="front", up="up")

    assert left_leg.halving.cut.bb.height + brace.left_halving.cut.bb.height == 40 mm,
        "halvings add up to the brace's height"
}
