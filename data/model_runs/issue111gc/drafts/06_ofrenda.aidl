# REQUEST (06, holidays): a small ofrenda (a Day of the Dead home altar) for a sideboard.
# 4 mm ply. Three tiers: two stepped side panels 180 deep, 300 mm apart outside, whose steps
# stand 10 mm proud of the shelves (treads 60 deep, shelf tops at 70, 140 and 210 mm);
# three shelves 300 x 60 mm each held by one 30 mm tab at each end through a mortise in the
# sides. Behind them a back panel 320 wide: 220 mm straight, then a semicircular arch of
# radius 160 on top (380 tall in all), which the sides' back edges hold with three 20 mm
# tabs each. In the arch: seven marigolds cut out (12-petal rounded stars, 26 mm across),
# on a 132 mm radius from the arch's centre, from 15 to 165 deg, and "NUESTROS ABUELOS"
# engraved (sans, 12 mm) along a 95 mm radius over the top. It must fit a 600 x 400 bed.

import "std/joints.aidl"

thickness 4 mm

ply = 4 mm
tread = 60 mm
rise = 70 mm
lip = 10 mm
width = 300 mm
back_w = 320 mm
back_h = 220 mm
arch_r = 160 mm
ring_r = 132 mm
words_r = 95 mm

def marigold(a) -> hole {
    f = Star(center=polar((0, back_h), ring_r, a), points=12, outer_radius=13, inner_radius=9,
             tip_radius=2)
}

assembly ofrenda {
    def side_panel() -> solid {
        profile = Polygon([(0, 0), (3 * tread, 0), (3 * tread, 3 * rise + lip),
                           (2 * tread, 3 * rise + lip), (2 * tread, 2 * rise + lip),
                           (tread, 2 * rise + lip), (tread, rise + lip), (0, rise + lip)])
        lug = Rectangle(bottom_left=(3 * tread, 0), width=ply, height=back_h)
        back_tabs = tab_and_slot(part="tab", length=back_h, thickness=ply, tabs=3, tab=20 mm,
                                 screw=0, rotation=-90 deg, cx=3 * tread + ply, cy=back_h / 2)
        for k in range(3) {
            shelf_slot = tab_and_slot(part="slot", length=tread, thickness=ply, tabs=1, tab=30 mm,
                                      screw=0, cx=k * tread + tread / 2, cy=(k + 1) * rise - ply / 2)
        }
        Rigid(self)
    }
    def shelf_board() -> solid {
        board = Rectangle(center=(0, 0), width=width, height=tread)
        left_tab = tab_and_slot(part="tab", length=tread, thickness=ply, tabs=1, tab=30 mm, screw=0,
                                rotation=90 deg, cx=-width / 2, cy=0)
        right_tab = tab_and_slot(part="tab", length=tread, thickness=ply, tabs=1, tab=30 mm, screw=0,
                                 rotation=-90 deg, cx=width / 2, cy=0)
        Rigid(self)
    }

    left_side = side_panel()
    right_side = side_panel()
    for k in range(3) {
        shelf = shelf_board()
        Place(shelf, position=(0, k * tread + tread / 2, (k + 1) * rise - ply), face="up")
    }

    solid back {
        lower = Rectangle(bottom_left=(-back_w / 2, 0), width=back_w, height=back_h)
        arch = Circle(center=(0, back_h), radius=arch_r)
        # the lower half of the arch's circle lies inside the panel; nothing pokes below
        for s in [-1, 1] {
            side_slots = tab_and_slot(part="slot", length=back_h, thickness=ply, tabs=3, tab=20 mm,
                                      screw=0, rotation=90 deg, cx=s * (width / 2 - ply / 2),
                                      cy=back_h / 2)
        }
        for i in range(7) {
            flower = marigold(a=15 deg + i * 25 deg)
        }
        drawing words {
            ring = Circle(center=(0, back_h), radius=words_r, construction=true)
            t = Text("NUESTROS ABUELOS", along=ring, size=12)
        }
        Rigid(self)
    }

    # 3D: the front of the lowest tread at y = 0, the floor at z = 0
    Place(left_side, position=(-width / 2, 0, 0), face="right", up="up")
    Place(right_side, position=(width / 2 - ply, 0, 0), face="right", up="up")
    Place(back, position=(0, 3 * tread + ply, 0), face="front", up="up")

    # flat on the sheet
    RightOf(left_side, back, gap=8)
    AlignBottom(left_side, back)
    Above(right_side, left_side, gap=8)
    AlignLeft(right_side, left_side)
    RightOf(shelf[0], left_side, gap=8)
    AlignBottom(shelf[0], back)
    for k in range(1, 3) {
        Above(shelf[k], shelf[k - 1], gap=8)
        AlignLeft(shelf[k], shelf[k - 1])
    }

    assert len(shelf) == 3, "three tiers"
    assert shelf[0].board.width == 300 mm and shelf[0].board.height == 60 mm, "shelves 300 x 60"
    assert left_side.profile.bb.width == 180 mm, "180 deep"
    assert left_side.shelf_slot[1].slot[0].bb.center_y - left_side.shelf_slot[0].slot[0].bb.center_y == 70 mm,
        "tiers 70 apart"
    assert left_side.profile.bb.top - (left_side.shelf_slot[2].slot[0].bb.top) == 10 mm,
        "steps 10 proud of the shelf tops"
    assert back.lower.width == 320 mm and back.arch.radius == 160 mm, "back 320, arch R160"
    assert back.bb.height == 380 mm, "380 tall"
    assert len(back.flower) == 7, "seven marigolds"
    assert back.flower[0].f.bb.width <= 26 mm, "26 across"
    assert distance(back.words.t, back.flower[3]) >= 5 mm, "words clear of the flowers"
    assert back.bb.height <= 400 mm - 6 mm, "fits the bed's height"
}
