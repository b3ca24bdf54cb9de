# Request (kitchen): a flat-pack fruit bowl from 6 mm birch ply. Two identical arched ribs
# cross-halved at the bottom: each rib is a half-ring 300 mm across (outer radius 150 mm,
# band 30 mm wide, inner radius 120 mm), its bottom cut flat 140 mm below the rim line so
# the bowl stands on the two feet. The ribs cross at the bottom centre with a cross halving,
# each cut 10 mm (half the 20 mm of rib left there): one from the foot up, one from the
# inside down. Each rib end carries a 15 mm wide tenon, 6 mm tall, that goes through a
# mortise in a flat rim ring (316 mm outside, 224 mm inside) so the ring sits flush with the
# tenon tips. Engrave "EAT MORE FRUIT" along the ring between two mortises, 8 mm letters.

units mm
thickness 6 mm
kerf 0.15 mm

import "std/joints.aidl"

param ply = 6 mm, min = 3 mm, max = 9 mm
outer_r = 150 mm
band = 30 mm
inner_r = outer_r - band
foot_drop = 140 mm          # from the rim line (rib ends) down to the flat foot
overlap = foot_drop - inner_r   # rib material left at the bottom centre: 20 mm
tenon_w = 15 mm
ring_outer_d = 316 mm
ring_inner_d = 224 mm
mid_r = (outer_r + inner_r) / 2

# one rib: the halving is cut from the foot (notch_y = -foot_drop, turned 180 deg to run up)
# or from the inner edge (notch_y = -inner_r, running down)
def rib(notch_y=-140 mm, notch_rot=180 deg) -> solid {
    arch = Sector(center=(0, 0), radius=outer_r, inner_radius=inner_r,
                  start_angle=180 deg, end_angle=360 deg)
    keep = Rectangle(center=(0, -foot_drop + 75 mm), width=2 * outer_r + 20 mm, height=150 mm)
    body = Intersect(arch, keep)
    halving = cross_halving(depth=overlap / 2, thickness=ply, clearance=0.1 mm,
                            rotation=notch_rot, cx=0 mm, cy=notch_y)
    left_tenon = tab_and_slot(part="tab", length=band, thickness=ply, tabs=1, tab=tenon_w,
                              screw=0, cx=-mid_r, cy=0 mm)
    right_tenon = tab_and_slot(part="tab", length=band, thickness=ply, tabs=1, tab=tenon_w,
                               screw=0, cx=mid_r, cy=0 mm)
}

assembly fruit_bowl {
    rib_a = rib(notch_y=-foot_drop, notch_rot=180 deg)
    rib_b = rib(notch_y=-inner_r, notch_rot=0 deg)

    solid ring {
        disc = Circle(center=(0, 0), diameter=ring_outer_d)
        hole middle { c = Circle(center=(0, 0), diameter=ring_inner_d) }
        m_east = tab_and_slot(part="slot", length=band, thickness=ply, tabs=1, tab=tenon_w,
                              screw=0, clearance=0.1 mm, cx=mid_r, cy=0 mm)
        m_west = tab_and_slot(part="slot", length=band, thickness=ply, tabs=1, tab=tenon_w,
                              screw=0, clearance=0.1 mm, cx=-mid_r, cy=0 mm)
        m_north = tab_and_slot(part="slot", length=band, thickness=ply, tabs=1, tab=tenon_w,
                               screw=0, clearance=0.1 mm, rotation=90 deg, cx=0 mm, cy=mid_r)
        m_south = tab_and_slot(part="slot", length=band, thickness=ply, tabs=1, tab=tenon_w,
                               screw=0, clearance=0.1 mm, rotation=90 deg, cx=0 mm, cy=-mid_r)
        drawing motto {
            track = Circle(center=(0, 0), radius=mid_r, construction=true)
            words = Text("EAT MORE FRUIT", along=track, angle=45 deg, size=8, valign="middle")
        }
        Fixed(disc)
        Concentric(middle.c, disc)
        Concentric(motto.track, disc)
    }

    # flat on the sheet: ribs side by side, the ring under them
    RightOf(rib_b, rib_a, gap=10)
    AlignTop(rib_b, rib_a)
    Below(ring, rib_a, gap=10)

    # assembled: rib A in the x-z plane, rib B in the y-z plane, the ring on the tenons
    Place(rib_a, rotation=(90 deg, 0, 0), position=(0, ply / 2, foot_drop))
    Place(rib_b, rotation=(90 deg, 0, 90 deg), position=(-ply / 2, 0, foot_drop))
    Place(ring, position=(0, 0, foot_drop - ply))

    # the request's numbers
    assert rib_a.body.bb.width == 300 mm, "ribs are 300 mm across"
    assert rib_a.body.bb.height == 140 mm - ply, "rim line to foot is 140 mm (shoulders 6 mm below the tips)"
    assert rib_a.bb.height == 140 mm, "tenon tips to foot 140 mm"
    assert ring.disc.diameter == 316 mm, "ring 316 mm outside"
    assert ring.middle.c.diameter == 224 mm, "ring 224 mm inside"
    assert rib_a.halving.depth + rib_b.halving.depth == 20 mm, "halvings meet: 10 + 10 of the 20 mm left"
    assert ring_inner_d / 2 < inner_r + 5 mm and ring_outer_d / 2 > outer_r + 5 mm, "ring covers the rib ends"
}
