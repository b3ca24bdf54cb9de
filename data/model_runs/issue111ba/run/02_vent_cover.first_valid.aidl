# Request (bathroom): a cover for the 100 mm extractor-fan duct in the bathroom ceiling, cut
# from 3 mm white acrylic. Face plate 150 x 150 mm with 12 mm corner radii; four M4
# countersunk screw holes (8.5 mm heads) 12 mm in from the corners. The air passes through
# four rings of curved louvre slots, 5 mm wide, on radii 14, 23, 32 and 41 mm about the
# centre, each ring cut into four arcs with 6 mm bridges between them, every other ring
# turned 45 deg so the bridges do not line up. Behind the plate two glued locating rings,
# 99 mm outside (a push fit in the 100 mm duct) and 92 mm inside, centre the cover on the
# duct without covering any louvre.

units mm
thickness 3 mm
kerf 0.1 mm

import "std/fasteners.aidl"

param plate_w = 150 mm, min = 130 mm, max = 200 mm
corner_r = 12 mm
screw_inset = 12 mm
head_d = 8.5 mm
slot_w = 5 mm
bridge = 6 mm
radii = [14 mm, 23 mm, 32 mm, 41 mm]
ring_od = 99 mm
ring_id = 92 mm

# half the angle a bridge (plus the slot's round ends) takes on radius r
def half_gap(r) = (bridge + slot_w) / (2 * r) * 1 rad

def locating_ring() -> solid {
    disc = Circle(center=(0, 0), diameter=ring_od)
    hole bore { c = Circle(center=(0, 0), diameter=ring_id) }
}

assembly vent {
    solid face {
        plate = RoundedRectangle(center=(0, 0), width=plate_w, height=plate_w,
                                 corner_radius=corner_r)
        Fixed(plate)
        screw = clearance_hole(size=4, cx=-plate_w / 2 + screw_inset, cy=-plate_w / 2 + screw_inset)
        screws = CornerPattern(screw, plate, inset=screw_inset)
        Countersink(screw, diameter=head_d)
        hole louvres {
            for i in range(len(radii)) {
                for q in range(4) {
                    s = ArcSlot(center=(0, 0), radius=radii[i],
                                start_angle=q * 90 deg + (i % 2) * 45 deg + half_gap(radii[i]),
                                end_angle=(q + 1) * 90 deg + (i % 2) * 45 deg - half_gap(radii[i]),
                                width=slot_w)
                }
            }
        }
    }
    back_1 = locating_ring()
    back_2 = locating_ring()

    RightOf(back_1, face, gap=10)
    AlignTop(back_1, face)
    Below(back_2, back_1, gap=10)
    AlignLeft(back_2, back_1)

    Place(face, position=(0, 0, 0))
    Place(back_1, position=(0, 0, 3 mm))
    Place(back_2, position=(0, 0, 6 mm))

    assert face.plate.width == 150 mm and face.plate.height == 150 mm, "plate 150 x 150"
    assert len(face.screws) == 4, "four screws"
    assert len(face.louvres.s) == 4 and len(face.louvres.s[0]) == 4, "four rings of four louvres"
    assert radii[3] + slot_w / 2 < ring_id / 2 - 1 mm, "the rings cover no louvre"
    assert ring_od == 99 mm and ring_id == 92 mm, "ring 99 outside, 92 inside"
    assert screw_inset == 12 mm, "screws 12 mm in from the corners"
}
