# Request (workshop): a Thien-baffle dust separator lid for a 5-gallon bucket, cut from
# 6 mm MDF. Lid: a 310 mm disc with two 58.5 mm ports for 2.5" shop-vac hose cuffs: the
# inlet 85 mm from the centre (straight "up" on the drawing), the outlet in the centre.
# Under the lid a locating ring 262 mm outside, 240 mm inside, glued and held by eight M4
# countersunk screws (8.5 mm heads) on a 251 mm circle; the ring has 3.3 mm pilot holes
# under them. The baffle: a 250 mm disc hanging 50 mm below the lid with a 12 mm wide arc
# slot on a 113 mm radius running 300 degrees round, leaving 60 degrees solid under the
# inlet. Two spacers, 60 mm radial by 50 mm tall between lid and baffle, each with a 20 mm
# tenon top and bottom glued into mortises 75 mm either side of the centre.
# Engraved on the lid: "IN" beside the inlet, "TO VAC" under the outlet, and
# "THIEN SEPARATOR - 5 GAL" along the rim at the bottom.

import "std/joints.aidl"
import "std/fasteners.aidl"

units mm
t = 6 mm
thickness t
kerf 0.15 mm

lid_d = 310 mm
port_d = 58.5 mm
inlet_r = 85 mm
ring_od = 262 mm
ring_id = 240 mm
pcd = 251 mm
baffle_d = 250 mm
drop = 50 mm
slot_r = 113 mm
slot_w = 12 mm
solid_span = 60 deg
spacer_w = 60 mm
tenon = 20 mm
mortise_x = 75 mm

def spacer() -> solid {
    body = Rectangle(center=(0, 0), width=spacer_w, height=drop + 2 * t)
    top_tenon = tab_and_slot(part="tab", length=spacer_w, thickness=t, tabs=1, tab=tenon,
                             screw=0, cx=0, cy=(drop + 2 * t) / 2)
    bottom_tenon = tab_and_slot(part="tab", length=spacer_w, thickness=t, tabs=1, tab=tenon,
                                screw=0, cx=0, cy=-(drop + 2 * t) / 2, rotation=180 deg)
}

assembly separator {
    solid lid {
        disc = Circle(center=(0, 0), diameter=lid_d)
        hole inlet { c = Circle(center=(0, inlet_r), diameter=port_d) }
        hole outlet { c = Circle(center=(0, 0), diameter=port_d) }
        for k in range(8) {
            screws = clearance_hole(size=4, cx=polar((0, 0), pcd / 2, 22.5 deg + k * 45 deg).x,
                                    cy=polar((0, 0), pcd / 2, 22.5 deg + k * 45 deg).y)
        }
        Countersink(screws, diameter=8.5)
        mortise_r = tab_and_slot(part="slot", length=spacer_w, thickness=t, tabs=1, tab=tenon,
                                 screw=0, cx=mortise_x, cy=0)
        mortise_l = tab_and_slot(part="slot", length=spacer_w, thickness=t, tabs=1, tab=tenon,
                                 screw=0, cx=-mortise_x, cy=0)
        drawing labels {
            word_in = Text("IN", position=(port_d / 2 + 8, inlet_r), size=8, anchor="start",
                           valign="middle")
            word_out = Text("TO VAC", position=(0, -port_d / 2 - 14), size=8, valign="middle")
            rim = Circle(center=(0, 0), radius=138, construction=true)
            title = Text("THIEN SEPARATOR - 5 GAL", along=rim, flip=true, size=6)
        }
    }

    solid ring {
        outer = Circle(center=(0, 0), diameter=ring_od)
        hole bore { c = Circle(center=(0, 0), diameter=ring_id) }
        for k in range(8) {
            pilots = clearance_hole(size=3, cx=polar((0, 0), pcd / 2, 22.5 deg + k * 45 deg).x,
                                    cy=polar((0, 0), pcd / 2, 22.5 deg + k * 45 deg).y)
        }
    }

    solid baffle {
        disc = Circle(center=(0, 0), diameter=baffle_d)
        hole track {
            a = ArcSlot(center=(0, 0), radius=slot_r, start_angle=90 deg + solid_span / 2,
                        end_angle=90 deg + 360 deg - solid_span / 2, width=slot_w)
        }
        mortise_r = tab_and_slot(part="slot", length=spacer_w, thickness=t, tabs=1, tab=tenon,
                                 screw=0, cx=mortise_x, cy=0)
        mortise_l = tab_and_slot(part="slot", length=spacer_w, thickness=t, tabs=1, tab=tenon,
                                 screw=0, cx=-mortise_x, cy=0)
    }

    spacer_r = spacer()
    spacer_l = spacer()

    # the cutting layout: lid, ring and baffle in a row, spacers under the lid
    RightOf(ring, lid, gap=10)
    AlignTop(ring, lid)
    RightOf(baffle, ring, gap=10)
    AlignTop(baffle, lid)
    Below(spacer_r, lid, gap=10)
    AlignLeft(spacer_r, lid)
    Below(spacer_l, lid, gap=10)
    RightOf(spacer_l, spacer_r, gap=10)

    # in 3D: lid on top (z 0..6), ring under it, baffle 50 below the lid, spacers between
    Place(lid, position=(0, 0, 0))
    Place(ring, position=(0, 0, -t))
    Place(baffle, position=(0, 0, -drop - t))
    Place(spacer_r, position=(mortise_x, t / 2, -drop / 2), face="front", up="up")
    Place(spacer_l, position=(-mortise_x, t / 2, -drop / 2), face="front", up="up")

    # the request's numbers
    assert lid.disc.diameter == 310 mm
    assert lid.inlet.c.diameter == 58.5 mm and lid.outlet.c.diameter == 58.5 mm
    assert abs(distance(lid.inlet.c.center, lid.disc.center) - 85 mm) < 0.01 mm
    assert distance(lid.outlet.c.center, lid.disc.center) < 0.01 mm
    assert ring.outer.diameter == 262 mm and ring.bore.c.diameter == 240 mm
    assert len(lid.screws) == 8 and len(ring.pilots) == 8
    assert baffle.disc.diameter == 250 mm
    assert baffle.track.a.width == 12 mm and baffle.track.a.radius == 113 mm
    # the inlet lies wholly inside the ring's bore, so the air reaches the bucket
    assert 85 mm + 58.5 mm / 2 <= 240 mm / 2 - 2 mm, "inlet clear of the ring"
    # the screws land in the middle of the ring
    assert abs(251 mm / 2 - (262 mm + 240 mm) / 4) < 0.01 mm
    assert baffle.disc.diameter < ring.outer.diameter, "baffle fits in the bucket"
}
