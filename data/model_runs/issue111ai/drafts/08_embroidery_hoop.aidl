# Request (crafts): a 150 mm embroidery hoop, laser-cut from 6 mm birch ply, tightened by an
# M4 bolt and wing nut. Inner ring 150 mm outside, 8 mm wide; outer ring 152 mm inside (1 mm
# for the fabric each side), 8 mm wide, split at the top by a 4 mm cut through a lug 40 mm wide
# that stands 24 mm up from the ring's inside edge (top corners R3). Two ear plates, 20 mm
# wide and 24 mm tall above the ring, stand upright on the lug either side of the split
# (their middles 8 mm from the centre line), each glued by one 12 mm tenon, 6 mm long, into a
# 12.1 x 6.1 mm mortise in the lug, centred 12 mm above the ring's inside edge; a 4.5 mm bolt
# hole in each plate, 12 mm above the lug. "HANDMADE BY NELL" engraved 4 mm high round the top
# of the inner ring, on the middle of its band.

units mm
thickness 6 mm
import "std/joints.aidl"

ply = 6 mm
inner_od = 150 mm
band = 8 mm
fabric = 1 mm
outer_id = inner_od + 2 * fabric
split = 4 mm
lug_w = 40 mm
lug_h = 24 mm
plate_w = 20 mm
plate_h = 24 mm
tenon = 12 mm
ear_x = 8 mm             # an ear plate's middle, from the centre line
bolt_d = 4.5 mm

def ear_plate() -> solid {
    # upright above the lug, its tenon below (the shoulder at y = 0)
    body = Rectangle(bottom_left=(-plate_w / 2, -ply), width=plate_w, height=plate_h + ply)
    foot = tab_and_slot(part="tab", length=plate_w, thickness=ply, tabs=1, tab=tenon, screw=0,
                        rotation=180 deg, cx=0 mm, cy=-ply)
    hole bolt { c = Circle(center=(0, 12), diameter=bolt_d) }
}

assembly hoop {
    solid outer_ring {
        rim = Circle(center=(0, 0), diameter=outer_id + 2 * band)
        lug = Rectangle(center=(0, outer_id / 2 + lug_h / 2), width=lug_w, height=lug_h)
        Fillet([lug.top_left, lug.top_right], 3)
        hole bore { c = Circle(center=(0, 0), diameter=outer_id) }
        hole cut {
            s = Rectangle(center=(0, outer_id / 2 + lug_h / 2), width=split, height=lug_h + 20,
                          overrun=true)
        }
        mortise_l = tab_and_slot(part="slot", length=plate_w, thickness=ply, tabs=1, tab=tenon,
                                 screw=0, clearance=0.1 mm, rotation=90 deg, cx=-ear_x,
                                 cy=outer_id / 2 + 12 mm)
        mortise_r = tab_and_slot(part="slot", length=plate_w, thickness=ply, tabs=1, tab=tenon,
                                 screw=0, clearance=0.1 mm, rotation=90 deg, cx=ear_x,
                                 cy=outer_id / 2 + 12 mm)
    }

    solid inner_ring {
        rim = Circle(center=(0, 0), diameter=inner_od)
        hole bore { c = Circle(center=(0, 0), diameter=inner_od - 2 * band) }
        drawing mark {
            path = Circle(center=(0, 0), radius=inner_od / 2 - band / 2, construction=true)
            t = Text("HANDMADE BY NELL", along=path, size=4, valign="middle")
        }
    }
    RightOf(inner_ring, outer_ring, gap=10)
    AlignBottom(inner_ring, outer_ring)

    ear_a = ear_plate()
    ear_b = ear_plate()
    RightOf(ear_a, inner_ring, gap=10)
    AlignTop(ear_a, outer_ring)
    RightOf(ear_b, ear_a, gap=10)
    AlignTop(ear_b, ear_a)

    assert inner_ring.rim.diameter == 150 mm, "150 mm hoop"
    assert outer_ring.bore.c.diameter - inner_ring.rim.diameter == 2 * 1 mm,
        "1 mm for the fabric each side"
    assert (inner_ring.rim.diameter - inner_ring.bore.c.diameter) / 2 == 8 mm,
        "8 mm inner band"
    assert (outer_ring.rim.diameter - outer_ring.bore.c.diameter) / 2 == 8 mm,
        "8 mm outer band"
    assert outer_ring.cut.s.width == 4 mm, "4 mm split"
    assert outer_ring.lug.width == 40 mm and outer_ring.lug.height == 24 mm, "lug 40 x 24"
    assert ear_a.body.width == 20 mm and ear_a.body.height - ply == 24 mm, "plates 20 x 24"
    assert outer_ring.mortise_r.cx - outer_ring.mortise_l.cx == 2 * 8 mm,
        "plates' middles 8 mm either side"
    assert ear_a.bolt.c.diameter == 4.5 mm, "4.5 mm bolt holes"
    assert ear_a.bolt.c.center.y - ear_a.body.bb.bottom - ply == 12 mm,
        "bolt 12 mm above the lug"
    assert ear_x - ply / 2 > split / 2, "the plates stand clear of the split"
}
