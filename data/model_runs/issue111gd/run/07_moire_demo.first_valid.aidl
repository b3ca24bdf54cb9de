# Request (science): a hand-held moire demonstrator from 3 mm black acrylic, for a school
# light-and-waves lesson. Two radial gratings held up against a window: disc A, 150 mm across
# with 24 round knurls (R4) on its rim to turn it, 60 wedge openings; disc B, 150 mm across
# on a 30 mm wide handle reaching 160 mm below its centre (round end, a 6 mm hanging hole
# 12 mm from the end), 64 wedge openings. Each opening is half its pitch, from 25 mm to 62 mm
# radius, so a spoke is at least 1.2 mm wide at the hub. Both discs bolt together with an M4
# bolt (4.3 mm holes) through a 16 mm spacer washer; disc B has a second 4.3 mm hole 8 mm off
# centre to show the off-centre fringes. Engraved: "60" and "64" on the hubs, "MOIRÉ" filled
# (bold sans, 9 mm) along the handle.

import "std/shapes.aidl"

thickness 3 mm

r_disc = 75 mm
r_in = 25 mm
r_out = 62 mm
bolt = 4.3 mm

assembly demo {
    solid disc_a {
        body = Circle(center=(0, 0), radius=r_disc)
        knurl = Circle(center=(r_disc, 0), radius=4)
        knurls = CircularPattern(knurl, 24, body.center)
        hole opening {
            s = Sector(center=(0, 0), radius=r_out, inner_radius=r_in, start_angle=0 deg,
                       end_angle=360 deg / 60 / 2)
        }
        openings = CircularPattern(opening, 60, body.center)
        hole axle {
            c = Circle(center=(0, 0), diameter=bolt)
        }
        drawing mark {
            n = Text("60", position=(0, -16), size=5, valign="middle")
        }
    }

    solid disc_b {
        body = Circle(center=(0, 0), radius=r_disc)
        handle = RoundedRectangle(corner=(-15, -160), opposite=(15, -60),
                                  corner_radii=[0 mm, 0 mm, 15 mm, 15 mm])
        hole opening {
            s = Sector(center=(0, 0), radius=r_out, inner_radius=r_in, start_angle=0 deg,
                       end_angle=360 deg / 64 / 2)
        }
        openings = CircularPattern(opening, 64, body.center)
        hole axle {
            c = Circle(center=(0, 0), diameter=bolt)
        }
        hole offset {
            c = Circle(center=(8, 0), diameter=bolt)
        }
        hole hang {
            c = Circle(center=(0, -148), diameter=6)
        }
        drawing mark {
            n = Text("64", position=(0, -16), size=5, valign="middle")
            title = Text("MOIRÉ", position=(0, -112), size=9, rotation=90 deg, font="sans:Bold",
                         valign="middle", fill=true)
        }
    }

    spacer = washer(outer=16 mm, inner=bolt)

    # flat on the sheet
    RightOf(disc_a, disc_b, gap=8)
    AlignTop(disc_a, disc_b)
    Below(spacer, disc_a, gap=8)
    AlignLeft(spacer, disc_a)

    # assembled: B, the washer, A on one bolt
    Place(disc_b, position=(0, 0, 0), face="up")
    Place(spacer, position=(0, 0, 3 mm), face="up")
    Place(disc_a, position=(0, 0, 6 mm), face="up")

    assert disc_a.body.diameter == 150 mm and disc_b.body.diameter == 150 mm, "150 discs"
    assert len(disc_a.knurls) == 24, "24 knurls"
    assert len(disc_a.openings) == 60 and len(disc_b.openings) == 64, "60 and 64 openings"
    assert disc_b.handle.bb.width == 30 mm, "handle 30 wide"
    assert disc_b.body.center.y - disc_b.handle.bb.bottom == 160 mm, "handle 160 below centre"
    assert disc_b.hang.c.center.y - disc_b.handle.bb.bottom == 12 mm, "hang hole 12 from the end"
    assert 2 * pi * r_in / 64 / 2 >= 1.2 mm, "B's spokes 1.2 at the hub"
    assert 2 * pi * r_in / 60 / 2 >= 1.2 mm, "A's spokes 1.2 at the hub"
    assert distance(disc_b.offset.c.center, disc_b.axle.c.center) == 8 mm, "offset hole 8 off"
    assert spacer.ring.diameter == 16 mm, "16 washer"
    assert distance(disc_b.mark, disc_b.hang) >= 2 mm, "title clear of the hanging hole"
    assert distance(disc_b.mark.n, disc_b.offset) >= 1 mm, "64 clear of the offset hole"
}
