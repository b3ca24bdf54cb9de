# Request: a bathroom towel shelf in 9 mm waterproof birch ply. A 600 x 230 mm
# shelf (front corners R8) with fifteen 10 x 150 mm airing slots at a 30 mm pitch,
# running front to back. It sits on two curved brackets 500 mm apart centre to
# centre; each bracket is 250 mm tall and 220 mm deep (from the wall), a curved
# brace running from under the shelf's front down to a rounded foot near the
# wall. Each bracket is glued with two 40 mm tabs into closed slots in the shelf
# and two into a 600 x 241 mm back plate that sits under the shelf and is screwed
# to the wall with five 4.5 mm screws (three along the top, two along the bottom,
# 30 mm in from those edges, countersunk 9 mm). A 20 mm dowel towel bar runs
# through a 20.5 mm hole in each bracket's foot, 70 mm out from the wall and
# 25 mm above the bracket's bottom.

import "std/joints.aidl"

thickness 9 mm

param span = 500 mm, min = 300 mm, max = 540 mm
shelf_w = 600 mm
shelf_d = 230 mm
br_h = 250 mm
br_d = 220 mm
t = 9 mm

def bracket() -> solid {
    back = Rectangle(bottom_left=(0, 0), width=30, height=br_h)
    band = Rectangle(bottom_left=(0, br_h - 40 mm), width=br_d, height=40)
    foot = Rectangle(bottom_left=(0, 0), width=70, height=35)
    lobe = Circle(center=(70, 25), radius=25)
    # the brace: a 24 mm band on a circle about the bracket's front bottom corner
    brace = ArcSlot(center=(220, 20), radius=190, start_angle=92 deg, end_angle=176 deg,
                    width=24)
    hole bar { c = Circle(center=(70, 25), diameter=20.5) }
    # glued tabs: the top edge into the shelf, the back edge into the back plate
    top_j = tab_and_slot(part="tab", length=br_d, thickness=t, tabs=2, tab=40 mm, screw=0,
                         rotation=0 deg, cx=br_d / 2, cy=br_h)
    back_j = tab_and_slot(part="tab", length=br_h, thickness=t, tabs=2, tab=40 mm, screw=0,
                          rotation=90 deg, cx=0 mm, cy=br_h / 2)
    Fillet([band.bottom_right], 10)
    Fillet(brace, band, 12)
    Fillet(brace, back, 12)
    Fillet(brace, foot, 12)
}

assembly towel_shelf {
    solid shelf {
        board = RoundedRectangle(center=(0, 0), width=shelf_w, height=shelf_d,
                                 corner_radii=[0, 0, 8, 8])
        hole airing {
            for i in range(15) {
                s = Slot(center=(-210 + i * 30, -10), length=150, width=10, rotation=90)
            }
        }
        # mortises: the rear edge (+y) is on the wall, the brackets' tabs are
        # measured from there
        ml = tab_and_slot(part="slot", length=br_d, thickness=t, tabs=2, tab=40 mm, screw=0,
                          rotation=90 deg, cx=-span / 2, cy=shelf_d / 2 - br_d / 2)
        mr = tab_and_slot(part="slot", length=br_d, thickness=t, tabs=2, tab=40 mm, screw=0,
                          rotation=90 deg, cx=span / 2, cy=shelf_d / 2 - br_d / 2)
        Fixed(board)
    }

    solid plate {
        body = Rectangle(center=(0, 0), width=shelf_w, height=br_h - t)
        hole top_screw { c = Circle(center=(-150, (br_h - t) / 2 - 30 mm), diameter=4.5) }
        tops = LinearPattern(top_screw, 3, (150, 0))
        hole low_screw { c = Circle(center=(-150, -(br_h - t) / 2 + 30 mm), diameter=4.5) }
        lows = LinearPattern(low_screw, 2, (300, 0))
        Countersink(tops + lows, diameter=9)
        # mortises for the brackets' back edges; the plate's bottom is the brackets' bottom
        pl = tab_and_slot(part="slot", length=br_h, thickness=t, tabs=2, tab=40 mm, screw=0,
                          rotation=90 deg, cx=-span / 2, cy=-(br_h - t) / 2 + br_h / 2)
        pr = tab_and_slot(part="slot", length=br_h, thickness=t, tabs=2, tab=40 mm, screw=0,
                          rotation=90 deg, cx=span / 2, cy=-(br_h - t) / 2 + br_h / 2)
        Fixed(body)
    }

    left = bracket()
    right = bracket()

    # flat: the plate under the shelf, the brackets to the right
    Below(plate, shelf, gap=10)
    AlignLeft(plate, shelf)
    RightOf(left, shelf, gap=10)
    AlignTop(left, shelf)
    RightOf(right, left, gap=10)
    AlignTop(right, left)

    # assembled: the wall is the plane y = 0, the room at -y
    Place(plate, position=(0, 0, (br_h - t) / 2), face="front", up="up")
    Place(left, position=(-span / 2 + t / 2, 0, 0), face="left", up="up")
    Place(right, position=(span / 2 + t / 2, 0, 0), face="left", up="up")
    Place(shelf, position=(0, -shelf_d / 2, br_h - t), face="up", up="back")

    assert shelf.board.width == 600 mm and shelf.board.height == 230 mm, "shelf 600 x 230"
    assert len(shelf.airing.s) == 15, "fifteen airing slots"
    assert shelf.airing.s[1].center.x - shelf.airing.s[0].center.x == 30 mm, "30 mm pitch"
    assert shelf.airing.s[0].length == 150 mm and shelf.airing.s[0].width == 10 mm, "10 x 150 slots"
    assert distance(shelf.airing, shelf.ml) >= 10 mm, "slots clear of the mortises"
    assert shelf.mr.slot[0].bb.center_x - shelf.ml.slot[0].bb.center_x == 500 mm, "brackets 500 apart"
    assert plate.pr.slot[0].bb.center_x - plate.pl.slot[0].bb.center_x == 500 mm, "brackets 500 apart"
    assert left.back.height == 250 mm, "bracket 250 tall"
    assert left.band.bb.right - left.back.bb.left == 220 mm, "bracket 220 deep"
    assert left.bar.c.diameter == 20.5 mm, "20.5 mm bar hole"
    assert left.bar.c.center.x - left.back.bb.left == 70 mm, "bar 70 mm out from the wall"
    assert left.bar.c.center.y - left.back.bb.bottom == 25 mm, "bar 25 mm up"
    assert len(tops) + len(lows) == 5, "five screws"
    assert plate.body.width == 600 mm and plate.body.height == 241 mm, "plate 600 x 241"
    assert plate.body.bb.top - tops[0].c.center.y == 30 mm, "top screws 30 mm in"
    assert lows[0].c.center.y - plate.body.bb.bottom == 30 mm, "bottom screws 30 mm in"
}
