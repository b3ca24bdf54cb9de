# Request: a mounting board for the 2-way passive crossover in my bookshelf speakers. 3 mm ply,
# 120 x 80 mm with R4 corners, an M4 clearance hole (4.5 mm) 6 mm in from each corner. The
# parts are held by cable ties (3.6 mm ties: slots 5 x 2 mm, long across the strap) and their
# footprints engraved as a placing guide: the inductor L1 (34 mm air coil) centred at (-30, 8)
# from the board's centre with a tie slot 21 mm either side of it; the film cap C1 (40 x 18)
# centred at (25, 18) with two ties 24 mm apart across it; the cement resistor R1 (48 x 10)
# centred at (25, -8) with two ties 30 mm apart. Six 4 mm wire holes in a row 15 mm apart,
# 8 mm above the bottom edge, labelled IN+ IN- WF+ WF- TW+ TW-. Engrave "XO-2 LEFT" top left.
# Under the left and right edges, two 6 mm ply rails 80 x 12 with matching screw holes lift
# the board so the tie heads clear the cabinet floor.

import "std/fasteners.aidl"

thickness 3 mm

def wire_hole() -> hole {
    c = Circle(center=(0, 0), diameter=4)
}

def tie_slot(rotation=0 deg) -> hole {
    s = Slot(center=(0, 0), length=5, width=2, rotation=rotation)
}

def rail() -> solid {
    thickness 6 mm
    r = Rectangle(center=(0, 0), width=12, height=80)
    top_screw = clearance_hole(size=4, cy=34)
    bottom_screw = clearance_hole(size=4, cy=-34)
}

assembly crossover {
    solid board {
        body = RoundedRectangle(center=(0, 0), width=120, height=80, corner_radius=4)
        screw = clearance_hole(size=4)
        screws = CornerPattern(screw, body, inset=6)

        # tie slots: L1's strap runs along x (slots long along y), C1's and R1's along y
        l1_a = tie_slot(rotation=90, cx=-51, cy=8)
        l1_b = tie_slot(rotation=90, cx=-9, cy=8)
        c1_a = tie_slot(cx=13, cy=6)
        c1_b = tie_slot(cx=13, cy=30)
        c1_c = tie_slot(cx=37, cy=6)
        c1_d = tie_slot(cx=37, cy=30)
        r1_a = tie_slot(cx=10, cy=-16)
        r1_b = tie_slot(cx=10, cy=0)
        r1_c = tie_slot(cx=40, cy=-16)
        r1_d = tie_slot(cx=40, cy=0)

        wire = wire_hole(cx=-37.5, cy=-32)
        wires = LinearPattern(wire, 6, (15, 0))

        drawing guide {
            l1 = Circle(center=(-30, 8), diameter=34)
            c1 = Rectangle(center=(25, 18), width=40, height=18)
            r1 = Rectangle(center=(25, -8), width=48, height=10)
            l1_name = Text("L1 1.5mH", position=(-30, 8), size=2.5, valign="middle")
            c1_name = Text("C1 4.7uF", position=(25, 18), size=3, valign="middle")
            r1_name = Text("R1 8R2 10W", position=(25, -8), size=3, valign="middle")
            title = Text("XO-2 LEFT", position=(-30, 30), size=4)
        }
        drawing names {
            tags = ["IN+", "IN-", "WF+", "WF-", "TW+", "TW-"]
            for i in range(6) {
                t = Text(tags[i], position=(-37.5 + i * 15, -25), size=3)
            }
        }
    }
    solid rail_l = rail()
    rail_r = rail()
    RightOf(rail_l, board, gap=5)
    AlignTop(rail_l, board)
    RightOf(rail_r, rail_l, gap=5)
    AlignTop(rail_r, rail_l)

    Place(rail_l, position=(-54, 0, 0))
    Place(rail_r, position=(54, 0, 0))
    Place(board, position=(0, 0, 6))

    assert board.body.bb.width == 120 mm and board.body.bb.height == 80 mm, "board 120 x 80"
    assert len(board.screws) == 4, "four screws"
    assert board.screws[0].c.center.x - board.body.bb.left == 6 mm, "screws 6 in (x)"
    assert board.screws[0].c.center.y - board.body.bb.bottom == 6 mm, "screws 6 in (y)"
    assert board.screw.c.diameter == 4.5 mm, "M4 clearance 4.5"
    assert len(board.wires) == 6, "six wire holes"
    assert board.wires[1].c.center.x - board.wires[0].c.center.x == 15 mm, "15 apart"
    assert board.wire.c.center.y - board.body.bb.bottom == 8 mm, "8 above the bottom"
    assert board.l1_b.s.center.x - board.guide.l1.center.x == 21 mm, "L1 tie 21 from its centre"
    assert board.c1_b.s.center.y - board.c1_a.s.center.y == 24 mm, "C1 ties 24 apart"
    assert board.r1_c.s.center.x - board.r1_a.s.center.x == 30 mm, "R1 ties 30 apart"
    assert rail_l.r.height == 80 mm and rail_l.r.width == 12 mm, "rails 80 x 12"
    assert distance(board.names, board.guide) >= 1 mm, "wire labels clear of the footprints"
}
