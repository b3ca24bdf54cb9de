# Request (sport): a garden cricket wicket for the kids that stands on the lawn or the
# patio, from 9 mm ply.
# - Base: a closed finger-jointed box 260 x 80 x 60 mm (15 mm fingers), "HOWZAT!" filled-
#   engraved on its front. Three slots through its lid and through its bottom for the
#   stumps (stump + 0.3 mm), the stumps' centres 101 mm apart.
# - Three stumps 28 mm wide, standing 500 mm above the base (they go through the base to
#   the ground: 560 mm long), top corners R3, a groove 20 mm wide x 6 mm deep in each top.
# - Two bails, each a bar 104 x 11 mm with a tongue 8 mm wide x 6 mm deep under each end
#   (flush with the end), the tongues resting in the grooves: the outer stump's alone, the
#   middle one's shared with the other bail, 2 mm between the two bails.
# The wicket is 230 mm wide over the outer stumps.

units mm
thickness 9 mm
import "std/joints.aidl"

t = 9 mm
box_h = 60 mm
pitch = 101 mm        # between the stumps' centres
stump_w = 28 mm
stump_l = 560 mm
groove_w = 20 mm
groove_d = 6 mm
bail_l = 104 mm
bail_h = 11 mm
tongue_w = 8 mm
bail_gap = 2 mm
bail_x = bail_gap / 2 + bail_l / 2   # a bail's middle from the wicket's middle
fit = 0.3 mm

def stump() -> solid {
    # x across the wicket from the stump's middle, y up from the ground
    body = RoundedRectangle(center=(0, stump_l / 2), width=stump_w, height=stump_l,
                            corner_radii=[3, 3, 0, 0])
    hole groove {
        g = Rectangle(center=(0, stump_l - groove_d / 2), width=groove_w, height=groove_d)
        g_out = Rectangle(center=(0, stump_l + 1), width=groove_w, height=2, overrun=true)
    }
}

def bail() -> solid {
    # x along the bail from its middle, y up from the stump tops (the tongues hang below)
    bar = Rectangle(center=(0, bail_h / 2), width=bail_l, height=bail_h)
    tongue_l = Rectangle(center=(-bail_l / 2 + tongue_w / 2, -groove_d / 2), width=tongue_w,
                         height=groove_d)
    tongue_r = Rectangle(center=(bail_l / 2 - tongue_w / 2, -groove_d / 2), width=tongue_w,
                         height=groove_d)
}

def stump_slots() -> hole {
    for i in range(3) {
        s = Rectangle(center=((i - 1) * pitch, 0), width=stump_w + fit, height=t + fit)
    }
}

assembly wicket {
    base = finger_box(length=260 mm, depth=80 mm, height=box_h, thickness=t, finger=15 mm,
                      closed=true)
    lid_slots = stump_slots()
    CenterInside(lid_slots, base.lid)
    CutInto(lid_slots, base.lid)
    bottom_slots = stump_slots()
    CenterInside(bottom_slots, base.bottom)
    CutInto(bottom_slots, base.bottom)
    drawing howzat {
        word = Text("HOWZAT!", position=(0, 0), size=24, valign="middle", font="sans:Bold",
                    fill=true)
    }
    CenterInside(howzat, base.front)
    CutInto(howzat, base.front)

    leg = stump()
    middle = stump()
    off = stump()
    bail_l_side = bail()
    bail_r_side = bail()

    # flat on the sheet: the stumps beside the box's net, the bails under them
    RightOf(leg, base, gap=10)
    AlignTop(leg, base)
    RightOf(middle, leg, gap=6)
    AlignTop(middle, leg)
    RightOf(off, middle, gap=6)
    AlignTop(off, leg)
    Below(bail_l_side, base, gap=10)
    AlignLeft(bail_l_side, base)
    RightOf(bail_r_side, bail_l_side, gap=6)
    AlignTop(bail_r_side, bail_l_side)

    # standing: the box on z = 0 centred on x = y = 0 (placed by finger_box), the stumps in
    # the plane y = 0 through its slots, the bails on top
    Place(leg, position=(-pitch, t / 2, 0), face="front", up="up")
    Place(middle, position=(0, t / 2, 0), face="front", up="up")
    Place(off, position=(pitch, t / 2, 0), face="front", up="up")
    Place(bail_l_side, position=(-bail_x, t / 2, stump_l), face="front", up="up")
    Place(bail_r_side, position=(bail_x, t / 2, stump_l), face="front", up="up")

    # the request's numbers
    assert stump_l - box_h == 500 mm, "500 mm above the base"
    assert 2 * pitch + stump_w == 230 mm, "230 mm over the outer stumps"
    assert base.lid.bb.width >= 260 mm - 0.1 mm, "base 260 long"
    assert lid_slots.s[2].center.x - lid_slots.s[0].center.x == 2 * 101 mm, "stumps 101 apart"
    assert middle.groove.g.width == 20 mm and middle.groove.g.height == 6 mm, "groove"
    assert bail_l_side.bar.width == 104 mm and bail_l_side.bar.height == 11 mm, "bail bar"
    # the bails' tongues land in the grooves with 2 mm between the bails
    assert 2 * (bail_x - bail_l / 2) == 2 mm, "2 mm between the bails"
    assert bail_x + bail_l / 2 <= pitch + groove_w / 2 and
        bail_x + bail_l / 2 - tongue_w >= pitch - groove_w / 2,
        "the outer tongue in the outer groove"
    assert bail_x - bail_l / 2 >= -groove_w / 2 and
        bail_x - bail_l / 2 + tongue_w <= groove_w / 2, "the inner tongue in the middle groove"
}
