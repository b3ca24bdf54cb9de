# Request (garden): a wall hanger for a coiled garden hose, 6 mm exterior ply. A back
# plate 220 wide x 200 high (R12 corners) hangs on two keyholes for 5 mm screws (10 mm head
# hole, 5.5 mm slot 12 long, upward) 60 mm either side of the centre and 25 mm below the
# top; two more 5 mm screws go through countersunk holes (10 mm heads) at the same x, 20 mm
# above the bottom. Three ribs stand out 130 mm from the plate's face, 75 mm apart, each
# glued into the plate by two 25 mm through tenons along a 120 mm back edge whose foot is
# 10 mm above the plate's bottom. Each rib: a humped saddle from the plate out to a front lip
# (the hump 15 mm higher in its middle than at its ends, which are 120 above the foot), a
# front lip 15 mm thick standing 30 mm above the saddle's ends, the underside running
# diagonally from 40 mm out at the foot to the lip 80 mm up, and a 44 mm lightening hole.

import "std/joints.aidl"
import "std/plates.aidl"
import "std/fasteners.aidl"

thickness 6 mm

ply = 6 mm
plate_w = 220 mm
plate_h = 200 mm
reach = 130 mm
back_h = 120 mm
hump = 15 mm
lip_t = 15 mm
lip_up = 30 mm
rib_pitch = 75 mm
foot_up = 10 mm
tenon = 25 mm

# the hump: a circular segment over the chord from the plate's face (x = ply) to the lip
chord = reach - lip_t
hump_r = (square(chord / 2) + square(hump)) / (2 * hump)

def rib() -> solid {
    # x = 0: the tenons' tips (the plate's back face); y = 0: the foot
    body = Polygon([(0, 0), (40, 0), (ply + reach, 80), (ply + reach, back_h + lip_up),
                    (ply + reach - lip_t, back_h + lip_up), (ply + reach - lip_t, back_h),
                    (0, back_h)])
    disc = Circle(center=(ply + chord / 2, back_h + hump - hump_r), radius=hump_r,
                  construction=true)
    band = Rectangle(bottom_left=(ply, back_h), width=chord, height=hump, construction=true)
    saddle = Intersect(disc, band)
    ten = tab_and_slot(part="tab", length=back_h, thickness=ply, tabs=2, tab=tenon, screw=0,
                       rotation=90 deg, cx=0 mm, cy=back_h / 2)
    hole lighten {
        c = Circle(center=(60, 55), diameter=44)
    }
}

assembly hose_hanger {
    solid plate {
        body = RoundedRectangle(center=(0, 0), width=plate_w, height=plate_h,
                                corner_radius=12)
        for i in range(2) {
            hang = keyhole(head=10 mm, slot_width=5.5 mm, length=12 mm, direction=90 deg,
                           cx=(i * 2 - 1) * 60 mm, cy=plate_h / 2 - 25 mm)
            screw = clearance_hole(size=5, cx=(i * 2 - 1) * 60 mm,
                                   cy=-plate_h / 2 + 20 mm)
        }
        Countersink(screw, diameter=10 mm)
        for k in range(3) {
            mort = tab_and_slot(part="slot", length=back_h, thickness=ply, tabs=2, tab=tenon,
                                screw=0, rotation=90 deg, cx=(k - 1) * rib_pitch,
                                cy=-plate_h / 2 + foot_up + back_h / 2)
        }
    }

    rib_a = rib()
    rib_b = rib()
    rib_c = rib()

    # flat: ribs in a row right of the plate
    RightOf(rib_a, plate, gap=10)
    AlignTop(rib_a, plate)
    RightOf(rib_b, rib_a, gap=10)
    AlignTop(rib_b, plate)
    RightOf(rib_c, rib_b, gap=10)
    AlignTop(rib_c, plate)

    # 3D: the plate on the wall (its back at y = ply, face to the front); each rib's x
    # runs out to -y from the plate's back face, its y up
    Place(plate, position=(0, ply, 0), face="front", up="up")
    Place(rib_a, position=(-rib_pitch + ply / 2, ply, -plate_h / 2 + foot_up), face="left",
          up="up")
    Place(rib_b, position=(ply / 2, ply, -plate_h / 2 + foot_up), face="left", up="up")
    Place(rib_c, position=(rib_pitch + ply / 2, ply, -plate_h / 2 + foot_up), face="left",
          up="up")

    assert plate.body.bb.width == 220 mm and plate.body.bb.height == 200 mm, "plate size"
    assert plate.hang[1].head_hole.center.x - plate.hang[0].head_hole.center.x == 120 mm,
        "keyholes 60 either side"
    assert plate.body.bb.top - plate.hang[0].head_hole.center.y == 25 mm, "keyholes 25 down"
    assert plate.screw[0].c.center.y - plate.body.bb.bottom == 20 mm, "screws 20 up"
    assert len(plate.mort) == 3, "three ribs"
    assert plate.mort[1].slot[0].bb.center_x - plate.mort[0].slot[0].bb.center_x == 75 mm,
        "ribs 75 apart"
    assert rib_a.bb.width - ply == 130 mm, "ribs stand out 130"
    assert rib_a.saddle.bb.height == 15 mm, "hump 15"
    assert rib_a.body.bb.height - back_h == 30 mm, "lip 30 above the saddle's ends"
    assert rib_a.lighten.c.diameter == 44 mm, "44 mm lightening hole"
    assert distance(rib_a.lighten, rib_a.ten) >= 5 mm, "lightening hole clear of the tenons"
    assert plate.mort[0].slot[0].bb.bottom - plate.body.bb.bottom >= 10 mm - 0.01 mm,
        "rib foot 10 up"
}
