# Request: toy binoculars for a four-year-old, a glued stack of five 6 mm poplar-ply layers.
# Every layer is two 56 mm barrels, centres 62 mm apart, joined by a 40 mm tall bridge, with
# two eye holes on the barrels' centres: 32 mm in the eyepiece layer (back), 40 mm in the
# three middle layers, 44 mm in the objective layer (front). The middle layer also has a
# cord lug on each side (16 mm round, centre 62 mm out from the middle, 5 mm hole 63 mm out)
# and a 14-tooth focus wheel standing on the bridge (star, 12 mm outer / 10 mm inner radius,
# 1 mm round tips, centre 22 mm above the middle). The front layer carries "SPY" engraved
# (bold, filled, 6 mm) between its eye holes.

thickness 6 mm

barrel_d = 56 mm
barrel_dx = 62 mm
eyes = [32 mm, 40 mm, 40 mm, 40 mm, 44 mm]

def layer(eye_d=40 mm, lugs=false, wheel=false, label="") -> solid {
    left = Circle(center=(-barrel_dx / 2, 0), diameter=barrel_d)
    right = Circle(center=(barrel_dx / 2, 0), diameter=barrel_d)
    bridge = Rectangle(center=(0, 0), width=barrel_dx, height=40)
    if lugs {
        lug_l = Circle(center=(-62, 0), diameter=16)
        lug_r = Circle(center=(62, 0), diameter=16)
        hole cord {
            l = Circle(center=(-63, 0), diameter=5)
            r = Circle(center=(63, 0), diameter=5)
        }
    }
    if wheel {
        focus = Star(center=(0, 22), points=14, outer_radius=12, inner_radius=10, tip_radius=1)
    }
    hole eyes {
        l = Circle(center=(-barrel_dx / 2, 0), diameter=eye_d)
        r = Circle(center=(barrel_dx / 2, 0), diameter=eye_d)
    }
    if label != "" {
        drawing name {
            t = Text(label, position=(0, 0), size=6, valign="middle", font="sans:Bold", fill=true)
        }
    }
}

assembly binoculars {
    for i in range(5) {
        l = layer(eye_d=eyes[i], lugs=(i == 2), wheel=(i == 2), label=("SPY" if i == 4 else ""))
        # assembled: stacked front to back, eyepiece layer at the back (y = 0), front layer's
        # face (and its engraving) looking forward
        Place(l, position=(0, -6 * i, 30), face="front", up="up")
    }
    # on the sheet: two rows
    for i in range(1, 5) {
        if i == 3 {
            Below(l[i], l[0], gap=8)
            AlignLeft(l[i], l[0])
        } else {
            RightOf(l[i], l[i - 1], gap=8)
            AlignTop(l[i], l[i - 1])
        }
    }

    assert len(l) == 5, "five layers"
    assert l[0].eyes.l.diameter == 32 mm, "eyepiece 32"
    assert l[1].eyes.l.diameter == 40 mm and l[2].eyes.r.diameter == 40 mm and l[3].eyes.l.diameter == 40 mm, "middle 40"
    assert l[4].eyes.r.diameter == 44 mm, "objective 44"
    assert distance(l[0].left.center, l[0].right.center) == 62 mm, "barrels 62 apart"
    assert l[0].left.diameter == 56 mm, "barrels 56"
    assert l[2].focus.center.y - l[2].bridge.center.y == 22 mm, "focus wheel 22 above the middle"
    assert l[2].cord.r.center.x - l[2].bridge.center.x == 63 mm, "cord hole 63 out"
    assert distance(l[4].name.t, l[4].eyes) >= 1.5 mm, "SPY clear of the eye holes"
    assert l[2].cord.r.center.x + 2.5 mm <= l[2].lug_r.bb.right - 3 mm, "at least 3 mm of lug round the cord hole"
}
