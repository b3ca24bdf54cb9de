# Request (workshop): a round dolly for the 19 l bucket my shop-vac separator sits on.
# Base: a 320 mm disc of 18 mm ply on four 50 mm swivel casters. Each caster's top plate
# is 64 x 64 mm with four M6 bolt holes (6.6 mm) on a 48 x 48 mm square; the casters' centres
# sit at 90 mm from the middle, at 45, 135, 225 and 315 deg, the squares square to the
# sheet. The bolts are M6 flat heads from the top: 12 mm countersinks, flush.
# Four 20 mm drain holes at 60 mm from the middle (0, 90, 180, 270 deg) so water from
# the bucket runs off, and "MAX 50 KG" engraved filled, bold, 8 mm high, in the middle.
# Locating ring: 6 mm ply, 320 mm outside, 272 mm inside (the bucket's foot is 265 mm),
# glued on top of the base, concentric; no countersink may be under the ring.

units mm

base_d = 320 mm
ring_id = 272 mm
pcd_r = 90 mm          # caster centre radius
sq = 48 mm             # bolt square
bolt_d = 6.6 mm
head_d = 12 mm
drain_r = 60 mm
drain_d = 20 mm

def caster_holes(x0, y0) -> hole {
    for k in range(4) {
        c = Circle(center=(x0 + (k % 2 - 0.5) * sq, y0 + (k // 2 - 0.5) * sq), diameter=bolt_d)
    }
}

assembly dolly {
    solid base {
        thickness 18 mm
        disc = Circle(center=(0, 0), diameter=base_d)
        for i in range(4) {
            caster = caster_holes(x0=pcd_r * cos(45 deg + i * 90 deg),
                                  y0=pcd_r * sin(45 deg + i * 90 deg))
        }
        Countersink(caster, diameter=head_d)
        hole drains {
            for j in range(4) {
                d = Circle(center=(drain_r * cos(j * 90 deg), drain_r * sin(j * 90 deg)),
                           diameter=drain_d)
            }
        }
        drawing label {
            t = Text("MAX 50 KG", (0, 0), size=8, font="sans:Bold", valign="middle", fill=true)
        }
        Fixed(disc)
    }

    solid ring {
        thickness 6 mm
        outer = Circle(center=(0, 0), diameter=320 mm)
        hole inside {
            c = Circle(center=(0, 0), diameter=ring_id)
        }
    }
    RightOf(ring, base, gap=10)
    AlignCenterY(ring, base)
    Place(ring, on=base, position=(0, 0))

    # the request's numbers
    assert base.disc.diameter == 320 mm, "base is 320 mm"
    assert ring.inside.c.diameter == 272 mm, "ring is 272 mm inside"
    assert ring.outer.diameter == 320 mm, "ring is 320 mm outside"
    assert len(base.caster) == 4, "four casters"
    assert base.caster[0].c[1].center.x - base.caster[0].c[0].center.x == 48 mm, "48 mm bolt square"
    assert base.caster[0].c[2].center.y - base.caster[0].c[0].center.y == 48 mm, "48 mm bolt square"
    # no countersink under the ring: every head inside the ring's 136 mm radius
    for i in range(4) {
        for k in range(4) {
            assert distance(base.caster[i].c[k].center, base.disc.center) + 12 mm / 2 <= 272 mm / 2,
                "countersink clear of the ring"
        }
    }
    assert distance(base.label, base.drains) >= 3 mm, "label clear of the drains"
}
