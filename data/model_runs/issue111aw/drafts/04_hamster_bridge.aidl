# Request (pets): an arched hamster bridge / hide from 3 mm birch ply. A deck 200 mm long and
# 90 mm wide whose middle 160 mm is a living hinge (cuts 15 mm long, 3 mm bridges, 2 mm pitch)
# so it bends into a half-round arch, its two 20 mm flat ends standing as the arch's legs.
# Two side ribs glued inside the deck's edges hold the shape: each a half ring 8 mm wide whose
# outer radius is the bent deck's inside radius, with 20 mm legs down to the floor. The
# hamster's name "PIP" engraved 8 mm tall on one leg. Show it assembled, bent.

import "std/plates.aidl"

units mm
thickness 3 mm

t = 3 mm
deck_l = 200 mm
deck_w = 90 mm
hinge_l = 160 mm
leg = 20 mm
rib_w = 8 mm
# a 180 degree bend is 180 deg x (inside radius + t / 2) long on the sheet
r_in = hinge_l / pi - t / 2

def rib() -> solid {
    arch = Sector(center=(0, leg), radius=r_in, inner_radius=r_in - rib_w, start_angle=0,
                  end_angle=180 deg)
    left_leg = Rectangle(bottom_left=(-r_in, 0), width=rib_w, height=leg)
    right_leg = Rectangle(bottom_left=(r_in - rib_w, 0), width=rib_w, height=leg)
}

assembly bridge {
    solid deck {
        body = Rectangle(center=(0, 0), width=deck_l, height=deck_w)
        flex = living_hinge(width=hinge_l, height=deck_w, pitch=2, cut=15, bridge=3, cx=0, cy=0)
        drawing name {
            n = Text("PIP", position=(-deck_l / 2 + leg / 2, 0), size=8, rotation=90 deg,
                     valign="middle")
        }
    }

    for i in range(2) {
        ribs = rib()
    }

    # flat on the sheet
    Below(ribs[0], deck, gap=8)
    AlignLeft(ribs[0], deck)
    RightOf(ribs[1], ribs[0], gap=8)
    AlignBottom(ribs[1], ribs[0])

    # assembled: the deck's first leg stands up from the floor (its x up, its bottom face
    # toward +x, inside the arch), bent over the top and down again
    Place(deck, rotation=(0, -90 deg, 0), position=(0, 0, deck_l / 2))
    Bend(deck, at=0, angle=-180 deg, radius=r_in)
    # the ribs stand in the x-z plane against the deck's edges, inside it
    Place(ribs[0], rotation=(90 deg, 0, 0), position=(r_in, deck_w / 2, 0))
    Place(ribs[1], rotation=(90 deg, 0, 0), position=(r_in, -deck_w / 2 + t, 0))

    # the request's own numbers
    assert deck.body.bb.width == 200 mm and deck.body.bb.height == 90 mm, "deck 200 x 90"
    assert abs(deck.flex.width - 160 mm) < 0.01, "hinge 160 long"
    assert abs(pi * (r_in + t / 2) - 160 mm) < 0.01, "the hinge makes a half round"
    assert (deck_l - hinge_l) / 2 == 20 mm, "20 mm legs"
    assert len(ribs) == 2, "two ribs"
    assert abs(ribs[0].arch.radius - ribs[0].arch.inner_radius - 8 mm) < 0.01, "ribs 8 wide"
    assert deck.name.bb.right < deck.flex.bb.left - 2, "name on the flat leg, clear of the hinge"
}
