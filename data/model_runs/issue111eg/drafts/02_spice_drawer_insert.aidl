# Request: a three-tier spice-jar insert for a kitchen drawer 300 mm wide and 85 mm tall
# inside, in 3 mm ply. The jars (45 mm across, 90 long) lie lid-forward on three decks,
# each deck 80 mm deep (front to back, measured level) sloping 15 deg down toward the back,
# where a riser stops the jars' bottoms. The decks rise 22 mm from tier to tier; the front
# deck's low (back) edge is 6 mm off the drawer floor. The two sides are the stepped
# profile; the decks (two 20 mm tenons an end) and the risers (one tenon half their height
# an end) are through-tenoned into the sides. The whole insert is 300 wide and must stand
# below the drawer's 85 mm.

units mm
thickness 3 mm
import "std/joints.aidl"

T = 3 mm
W_in = 300 mm - 2 * T     # between the sides
slope = 15 deg
run = 80 mm               # a deck's depth, level
P = run + T               # tier pitch: a deck and its riser
rise = 22 mm
back_lip = 22 mm          # the back riser above the last deck's low edge
# FIX after the first valid program: the sides stood flush with the decks' tops, so every
# mortise broke through the sides' top edge (W0530) and the back riser's mortise cut a
# sliver off the back (W0504). The sides now stand `rail` above the decks and risers and
# reach `rail` behind the back riser; the back riser is lower so the sides stay under 85 mm.
rail = 5 mm
def low(k) = 6 mm + k * rise              # a deck's back (low) edge, top face
def high(k) = low(k) + run * tan(slope)   # its front (high) edge, top face, level with the riser in front
def riser_h(k) = high(k + 1) if k < 2 else low(2) + back_lip
e = T * sin(slope)        # the deck's front end starts this far behind the riser in front, so its bottom corner clears it
L = (run - e) / cos(slope)   # a deck's length along its slope

def side_t() -> solid {
    profile = Intersect(Offset(Polygon([(0, 0), (0, high(0)), (run, low(0)), (run, high(1)),
                       (P, high(1)), (P + run, low(1)), (P + run, high(2)),
                       (2 * P, high(2)), (2 * P + run, low(2)), (2 * P + run, riser_h(2)),
                       (3 * P, riser_h(2)), (3 * P, 0)]), rail, join="miter"),
                       Rectangle(bottom_left=(0, 0), width=3 * P + rail, height=120))
    for k in range(3) {
        # the deck's middle plane: halfway along its top line, T / 2 under it
        deck_mortise = tab_and_slot(part="slot", length=L, thickness=T, tabs=2, tab=20 mm,
            screw=0, rotation=-slope,
            cx=P * k + (e + run) / 2 - T / 2 * sin(slope),
            cy=(high(k) - e * tan(slope) + low(k)) / 2 - T / 2 * cos(slope))
        riser_mortise = tab_and_slot(part="slot", length=riser_h(k), thickness=T, tabs=1,
            tab=riser_h(k) / 2, screw=0, rotation=90 deg,
            cx=P * k + run + T / 2, cy=riser_h(k) / 2)
    }
}

def deck_t() -> solid {
    board = Rectangle(center=(0, 0), width=W_in + 2 * T, height=L)
    left_tenons = tab_and_slot(part="tab", length=L, thickness=T, tabs=2, tab=20 mm, screw=0,
                               rotation=90 deg, cx=-(W_in / 2 + T), cy=0 mm)
    right_tenons = tab_and_slot(part="tab", length=L, thickness=T, tabs=2, tab=20 mm, screw=0,
                                rotation=-90 deg, cx=W_in / 2 + T, cy=0 mm)
}

def riser_t(h=40 mm) -> solid {
    board = Rectangle(bottom_left=(-(W_in / 2 + T), 0), width=W_in + 2 * T, height=h)
    left_tenon = tab_and_slot(part="tab", length=h, thickness=T, tabs=1, tab=h / 2, screw=0,
                              rotation=90 deg, cx=-(W_in / 2 + T), cy=h / 2)
    right_tenon = tab_and_slot(part="tab", length=h, thickness=T, tabs=1, tab=h / 2, screw=0,
                               rotation=-90 deg, cx=W_in / 2 + T, cy=h / 2)
}

assembly spice_insert {
    left_side = side_t()
    right_side = side_t()
    Place(left_side, position=(-(W_in / 2 + T), 0, 0), face="right", up="up")
    Place(right_side, position=(W_in / 2, 0, 0), face="right", up="up")

    for k in range(3) {
        deck = deck_t()
        riser = riser_t(h=riser_h(k))
        # the deck's top face centre sits on the middle of its top line
        Place(deck, position=(0, P * k + (e + run) / 2 - T * sin(slope),
                              (high(k) - e * tan(slope) + low(k)) / 2 - T * cos(slope)),
              rotation=(-slope, 0, 0))
        Place(riser, position=(0, P * k + run + T, 0), face="front", up="up")
    }

    # flat on the sheet: one column
    Below(right_side, left_side, gap=5)
    AlignLeft(right_side, left_side)
    RightOf(deck[0], left_side, gap=5)
    AlignTop(deck[0], left_side)
    Below(deck[1], deck[0], gap=5)
    AlignLeft(deck[1], deck[0])
    Below(deck[2], deck[1], gap=5)
    AlignLeft(deck[2], deck[0])
    Below(riser[0], deck[2], gap=5)
    AlignLeft(riser[0], deck[0])
    Below(riser[1], riser[0], gap=5)
    AlignLeft(riser[1], deck[0])
    Below(riser[2], riser[1], gap=5)
    AlignLeft(riser[2], deck[0])

    assert len(deck) == 3 and len(riser) == 3, "three tiers"
    assert deck[0].board.bb.width == 300 mm, "300 wide overall"
    assert left_side.profile.bb.height < 85 mm, "fits under the drawer's 85 mm"
    assert left_side.profile.bb.height <= 80 mm, "some room above the back riser"
    assert low(1) - low(0) == 22 mm, "22 mm tier to tier"
    assert low(0) == 6 mm, "front deck 6 mm off the floor"
    assert abs(L * cos(slope) + e - 80 mm) < 0.001 mm, "decks 80 deep level"
    assert riser_h(0) - low(0) >= 22 mm, "a riser stops at least half a 45 mm jar"
}
