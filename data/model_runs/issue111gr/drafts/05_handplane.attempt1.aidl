# Request: a bodysurfing handplane, two layers of 6 mm marine ply glued into a 12 mm deck.
# Outline 330 mm long (nose to the tips of a swallow tail) and 220 mm wide, smooth, with
# the swallow-tail notch 25 mm deep on the centre line; tips and notch sharp. A hand strap
# through two 40 x 5 mm slots, along the length, 110 mm apart (x = -55 and 55 mm), 20 mm
# forward of the middle, through both layers. An 8 mm leash hole on the centre line 125 mm
# behind the middle. Top layer: "SALTY" engraved filled in bold sans (28 mm) 80 mm forward
# of the middle, with an engraved wave line under it. Underneath, a small keel fin of 6 mm
# ply: a 70 mm base, 35 mm deep, swept back, glued with two 15 mm tabs into mortises
# (0.2 mm clearance) through the bottom layer, centred on the centre line 80 mm behind the
# middle.

import "std/joints.aidl"
import "std/plates.aidl"

t = 6 mm
thickness t

half = [(0, 165), (60, 150), (100, 110), (110, 40), (105, -40), (90, -110), (60, -150),
        (25, -165), (0, -140)]

def deck(top=true) -> solid {
    outline = Spline(half, closed=true, mirror="y", corners=[7, 8, 9])
    strap_l = slot(length=40 mm, width=5 mm, rotation=90 deg, cx=-55 mm, cy=20 mm)
    strap_r = slot(length=40 mm, width=5 mm, rotation=90 deg, cx=55 mm, cy=20 mm)
    hole leash { c = Circle(center=(0, -125), diameter=8) }
    if top {
        drawing logo {
            word = Text("SALTY", position=(0, 80), size=28, font="sans:Bold",
                        valign="middle", fill=true)
            wave = Spline([(-60, 55), (-40, 61), (-20, 55), (0, 49), (20, 55), (40, 61), (60, 55)])
        }
    } else {
        fin_slot = tab_and_slot(part="slot", length=70 mm, thickness=6 mm, tabs=2, tab=15 mm,
                                screw=0, clearance=0.2 mm, rotation=90 deg, cx=0 mm, cy=-80 mm)
    }
}

def keel_fin() -> solid {
    base = Rectangle(bottom_left=(-35, 0), width=70, height=6)
    blade = Spline([(-35, 0), (35, 0), (25, -12), (5, -28), (-18, -35), (-30, -24)],
                   closed=true, corners=[0, 1])
    tabs = tab_and_slot(part="tab", length=70 mm, thickness=6 mm, tabs=2, tab=15 mm, screw=0,
                        cx=0 mm, cy=6 mm)
}

assembly handplane {
    top = deck(top=true)
    bottom = deck(top=false)
    fin = keel_fin()

    RightOf(bottom, top, gap=6)
    AlignCenterY(bottom, top)
    RightOf(fin, bottom, gap=6)
    AlignCenterY(fin, bottom)

    Place(bottom, position=(0, 0, 0))
    Place(top, position=(0, 0, t))
    # the fin hangs under the deck along its centre line, tabs up into the bottom layer
    Place(fin, position=(-3 mm, -80 mm, 0), face="right", up="up")

    # the request's numbers
    assert abs(top.outline.points[0].y - top.outline.points[7].y - 330 mm) < 0.01 mm, "330 mm long"
    assert abs(top.outline.points[3].x - top.outline.points[13].x - 220 mm) < 0.01 mm, "220 mm wide"
    assert abs(top.outline.points[8].y - top.outline.points[7].y - 25 mm) < 0.01 mm, "swallow notch 25 mm deep"
    assert top.outline.bb.width <= 222 mm and top.outline.bb.height <= 331 mm, "the curve does not bulge past the size"
    assert abs(distance(top.strap_l.s.center, top.strap_r.s.center) - 110 mm) < 0.01 mm, "strap slots 110 mm apart"
    assert abs(top.strap_l.s.center.y - top.outline.points[7].y - (165 mm + 20 mm)) < 0.01 mm, "strap 20 mm forward of the middle"
    assert abs(top.leash.c.center.y - top.outline.points[7].y - (165 mm - 125 mm)) < 0.01 mm, "leash hole 125 mm behind the middle"
    assert abs(bottom.fin_slot.slot[0].bb.height - 15.2 mm) < 0.01 mm, "mortise 15 + 0.2 long"
    assert abs(bottom.fin_slot.slot[0].bb.width - 6.2 mm) < 0.01 mm, "mortise 6 + 0.2 wide"
    assert abs(fin.base.width - 70 mm) < 0.01 mm, "70 mm fin base"
    assert abs(fin.blade.bb.height - 35 mm) < 0.5 mm, "fin 35 mm deep"
    assert distance(top.logo, top.strap_l) >= 5 mm and distance(top.logo, top.strap_r) >= 5 mm, "logo clear of the strap slots"
    assert distance(bottom.leash, bottom.fin_slot) >= 8 mm, "leash hole clear of the fin"
}
