# Request: a hair-tie tower for the bathroom shelf, cut from 3 mm acrylic, three
# parts. Two fins cross-halved into a "+" form the post that scrunchies and hair
# ties are stacked over: each fin stands 150 mm above the base, 30 mm wide just
# above the base tapering to 16 mm, topped by a round knob 24 mm across that
# keeps the ties from sliding off. Each fin has a 20 mm wide tab, 3 mm long, that
# goes through a "+"-shaped mortise in the middle of a round base 90 mm across.
# Joints get 0.1 mm clearance for the acrylic. "HAIR TIES" is engraved round the
# top of the base.

import "std/joints.aidl"

units mm
thickness 3 mm

param sheet = 3 mm, min = 2 mm, max = 6 mm
param fit = 0.1 mm, min = 0 mm, max = 0.3 mm
param tall = 150 mm, min = 100 mm, max = 220 mm
param foot_w = 30 mm, min = 24 mm, max = 50 mm
param neck_w = 16 mm, min = 10 mm, max = 24 mm
param knob_d = 24 mm, min = 16 mm, max = 36 mm
param tab_w = 20 mm, min = 10 mm, max = 24 mm
param base_d = 90 mm, min = 70 mm, max = 140 mm

knob_y = tall - knob_d / 2            # the knob's centre above the base
overlap = tall + sheet                # where the fins cross they span tab tip to knob top
half = overlap / 2

# FIX after the first valid program: the halvings were placed by coordinates in
# the assembly and CutInto the fins; fin B moved away from its slot (W0502) and
# was cut with none. Each fin now carries its own halving.
def fin(from_top=1) -> solid {
    body = Trapezoid(center=(0, knob_y / 2), bottom_width=foot_w, top_width=neck_w,
                     height=knob_y)
    knob = Circle(center=(0, knob_y), diameter=knob_d)
    tab = Rectangle(center=(0, -sheet / 2), width=tab_w, height=sheet)
    if from_top == 1 {
        slot = cross_halving(depth=half, thickness=sheet, clearance=fit, cx=0 mm, cy=tall)
    } else {
        slot = cross_halving(depth=half, thickness=sheet, clearance=fit, rotation=180 deg,
                             cx=0 mm, cy=-sheet)
    }
}

assembly hair_tie_tower {
    # fin A is slotted from the top down, fin B from the tab up
    fin_a = fin(from_top=1)
    fin_b = fin(from_top=0)

    solid base {
        disc = Circle(center=(0, 0), diameter=base_d)
        hole mortise {
            along_x = Rectangle(center=(0, 0), width=tab_w + fit, height=sheet + fit)
            along_y = Rectangle(center=(0, 0), width=sheet + fit, height=tab_w + fit)
        }
        drawing label {
            ring = Circle(center=(0, 0), radius=base_d / 2 - 11, construction=true)
            words = Text("HAIR TIES", along=ring, size=6)
        }
    }

    RightOf(fin_b, fin_a, gap=10)
    RightOf(base, fin_b, gap=10)
    AlignBottom(fin_b, fin_a)
    AlignBottom(base, fin_a)

    assert fin_a.knob.bb.top - fin_a.body.bb.bottom == 150 mm, "fins stand 150 mm above the base"
    assert fin_a.body.bottom_width == 30 mm and fin_a.body.top_width == 16 mm, "fin tapers 30 to 16 mm"
    assert fin_a.knob.diameter == 24 mm, "knob 24 mm across"
    assert fin_a.tab.bb.width == 20 mm and fin_a.tab.bb.height == 3 mm, "tab 20 mm wide, 3 mm long"
    assert base.disc.diameter == 90 mm, "base 90 mm across"
    assert fin_a.slot.depth + fin_b.slot.depth == overlap, "the halvings meet"
}
