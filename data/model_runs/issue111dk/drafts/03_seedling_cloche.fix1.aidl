# Request (garden): a flat-pack seedling cloche frame that holds garden fleece over a row-end
# seedling, 6 mm exterior ply. Two semicircular arch hoops, 300 mm across outside and 150 mm
# high above the soil, the band 20 mm wide, cross-halved where they cross at the top (one
# slotted 10 mm down from the top, the other 10 mm up from below). Each arch foot ends in a
# 60 mm spike, 12 mm wide at the shoulder, that passes through a 12.4 x 6.2 mm slot in a flat
# ground ring (310 mm outside, 30 mm wide) so the band's shoulders rest on the ring and the
# two arches stand square. The ring carries "SWEET PEAS" and "SOWN APRIL 2026" engraved
# along it, between the slots.

import "std/joints.aidl"

units mm
thickness 6 mm

t = 6 mm
r_out = 150 mm
band = 20 mm
r_mid = r_out - band / 2
spike = 60 mm
spike_w = 12 mm
clear = 0.2 mm

# One arch: the arc's centre at (0, 0), the shoulders on y = 0, spikes below.
def arch(from_top=true) -> solid {
    hoop = Sector(center=(0, 0), radius=r_out, start_angle=0, end_angle=180,
                  inner_radius=r_out - band)
    for x in [-r_mid, r_mid] {
        # FIX after the first valid program: W0507, the 11 degree needle tips burn away;
        # each spike now ends in a 2 mm flat (still 60 mm long)
        sp = Polygon([(x - spike_w / 2, 1), (x + spike_w / 2, 1), (x + 1, -spike), (x - 1, -spike)])
    }
    if from_top {
        halving = cross_halving(depth=band / 2, thickness=t, clearance=clear, cx=0, cy=r_out)
    } else {
        halving = cross_halving(depth=band / 2, thickness=t, clearance=clear, cx=0,
                                cy=r_out - band, rotation=180 deg)
    }
}

solid_ring_r = r_mid

assembly cloche {
    arch_a = arch(from_top=true)
    arch_b = arch(from_top=false)

    solid ring {
        disc = Circle(center=(0, 0), radius=155)
        hole inner { c = Circle(center=(0, 0), radius=125) }
        hole feet {
            for a in [0, 90, 180, 270] {
                s = Rectangle(center=(r_mid * cos(a * 1 deg), r_mid * sin(a * 1 deg)),
                              width=spike_w + 2 * clear, height=t + 2 * clear, rotation=a * 1 deg)
            }
        }
        drawing words {
            guide = Circle(center=(0, 0), radius=r_mid, construction=true)
            w1 = Text("SWEET PEAS", along=guide, angle=135 deg, size=7, valign="middle")
            w2 = Text("SOWN APRIL 2026", along=guide, angle=315 deg, size=7, valign="middle",
                      flip=true)
        }
    }

    # flat on the sheet: the arches above the ring, one above the other
    Above(arch_a, ring, gap=10)
    AlignCenterX(arch_a, ring)
    Above(arch_b, arch_a, gap=10)
    AlignCenterX(arch_b, arch_a)

    # in 3D: the ring on the soil, the arches' shoulders on it, crossing at the top
    Place(ring, position=(0, 0, 0), face="up")
    Place(arch_a, position=(0, t / 2, t), face="front", up="up")
    Place(arch_b, position=(-t / 2, 0, t), face="right", up="up")

    # the request's numbers
    assert arch_a.hoop.bb.width == 300 mm and arch_a.hoop.bb.height == 150 mm, "arch 300 x 150"
    assert arch_a.hoop.width == 20 mm, "20 mm band"
    assert arch_a.bb.height - arch_a.hoop.bb.height == 60 mm, "60 mm spikes"
    assert arch_a.halving.depth + arch_b.halving.depth == 20 mm, "halvings add up to the band"
    assert ring.disc.diameter == 310 mm and ring.disc.radius - ring.inner.c.radius == 30 mm, "ring 310, 30 wide"
    assert len(ring.feet.s) == 4, "four foot slots"
}
