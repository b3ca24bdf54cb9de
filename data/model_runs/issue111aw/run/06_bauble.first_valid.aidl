# Request (holidays): a slot-together 3D Christmas bauble from 3 mm ply. Two discs 80 mm across
# that cross at right angles: one slotted from the top down to its centre, the other from the
# bottom up to its centre (slots 3 mm wide, halfway each). Each disc has four six-pointed star
# openings (8 mm outer, 4 mm inner radius) 24 mm from its centre, at 45, 135, 225 and 315
# degrees. On top of the bottom-slotted disc a rounded hanging tab 12 mm wide standing 10 mm
# proud of the disc, with a 4 mm hole for the ribbon. Show it assembled.

import "std/joints.aidl"
import "std/shapes.aidl"

units mm
thickness 3 mm

t = 3 mm
dia = 80 mm
star_r = 24 mm

def star_hole() -> hole {
    s = Star(center=(star_r * cos(45 deg), star_r * sin(45 deg)), points=6, outer_radius=8,
             inner_radius=4)
}

assembly bauble {
    solid disc_a {
        body = Circle(center=(0, 0), diameter=dia)
        slot = cross_halving(depth=dia / 2, thickness=t, cx=0, cy=dia / 2)
        first = star_hole()
        stars = CircularPattern(first, 4, body.center)
    }

    solid disc_b {
        body = Circle(center=(0, 0), diameter=dia)
        slot = cross_halving(depth=dia / 2, thickness=t, rotation=180 deg, cx=0, cy=-dia / 2)
        first = star_hole()
        stars = CircularPattern(first, 4, body.center)
        # the tab's base sits 4 mm inside the disc so it joins; it stands 10 mm proud
        hanger = rounded_tab(width=12, length=14, hole_d=4, cx=0, cy=dia / 2 - 4)
    }

    RightOf(disc_b, disc_a, gap=8)
    AlignBottom(disc_b.body, disc_a.body)

    # assembled: disc_a in the x-z plane, disc_b in the y-z plane, both centred on the z axis
    Place(disc_a, rotation=(90 deg, 0, 0), position=(0, t / 2, 0))
    Place(disc_b, rotation=(90 deg, 0, 90 deg), position=(-t / 2, 0, 0))

    # the request's own numbers
    assert disc_a.body.diameter == 80 mm and disc_b.body.diameter == 80 mm, "discs 80 across"
    assert disc_a.slot.depth + disc_b.slot.depth == 80 mm, "slots halfway each"
    assert len(disc_a.stars) == 4 and len(disc_b.stars) == 4, "four stars a disc"
    assert abs(disc_b.hanger.bb.top - disc_b.body.bb.top - 10 mm) < 0.01, "tab 10 proud"
    assert disc_b.hanger.eye.e.diameter == 4 mm, "4 mm ribbon hole"
    assert disc_b.hanger.eye.bb.bottom > disc_b.body.bb.top + 1, "ribbon hole clear of the disc"
}
