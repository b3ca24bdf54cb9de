# Request (office): a cable grommet for a 60 mm hole drilled in a desk top, cut from 6 mm
# ply. A flange ring 80 mm across with a 54.6 mm opening sits on the desk; under it two
# identical collar rings 59.6 mm across (0.4 mm clear in the 60 mm hole) with a 46 mm bore
# are glued, 12 mm deep in the hole. A 54 mm cap drops into the flange's opening and rests on
# the collar's ledge, flush with the flange; it has a cable notch 20 mm wide, 14 mm deep from
# its edge with a round end, and "CABLES" engraved 5 mm high opposite the notch.

thickness 6 mm

hole_d = 60 mm
flange_od = 80 mm
collar_od = 59.6 mm
collar_id = 46 mm
cap_d = 54 mm
cap_clear = 0.6 mm
notch_w = 20 mm
notch_deep = 14 mm

def ring(od, id) -> solid {
    disc = Circle(center=(0, 0), diameter=od)
    hole bore { c = Circle(center=(0, 0), diameter=id) }
}

assembly grommet {
    flange = ring(od=flange_od, id=cap_d + cap_clear)
    collar_a = ring(od=collar_od, id=collar_id)
    collar_b = ring(od=collar_od, id=collar_id)

    solid cap {
        disc = Circle(center=(0, 0), diameter=cap_d)
        hole notch {
            s = Slot(start=(0, cap_d / 2 - notch_deep + notch_w / 2), end=(0, cap_d / 2 + notch_w),
                     width=notch_w, overrun=true)
        }
        drawing label {
            word = Text("CABLES", position=(0, -12), size=5, valign="middle")
        }
        assert cap_d / 2 - (notch.s.start.y - notch_w / 2) == 14 mm, "notch 14 mm deep"
        assert notch.s.width == 20 mm, "notch 20 mm wide"
    }

    RightOf(collar_a, flange, gap=5)
    RightOf(collar_b, collar_a, gap=5)
    RightOf(cap, collar_b, gap=5)
    AlignCenterY(collar_a, flange)
    AlignCenterY(collar_b, flange)
    AlignCenterY(cap, flange)

    assert flange.disc.diameter == 80 mm, "flange 80 mm"
    assert hole_d - collar_a.disc.diameter == 0.4 mm, "collar 0.4 mm clear in the 60 mm hole"
    assert collar_a.bore.c.diameter == 46 mm, "collar bore 46"
    # the cap rests on the collar's ledge and the flange still grips the collar
    assert cap.disc.diameter > collar_id and cap.disc.diameter < flange.bore.c.diameter,
        "cap sits on the ledge, inside the flange"
    assert flange.bore.c.diameter < collar_od, "flange overlaps the collar to glue"
    # the notch reaches past the collar's bore so cables drop through
    assert cap_d / 2 - notch_deep < collar_id / 2, "notch opens into the bore"
}
