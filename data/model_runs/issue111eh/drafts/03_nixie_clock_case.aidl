# Request (electronics): a case for a 4-tube IN-14 nixie clock board, 3 mm plywood,
# finger-jointed. The board is 160 x 50 mm with M3 mounting holes 4 mm in from each corner,
# on 5 mm standoffs, 2 mm clearance to the walls, 35 mm deep inside (floor to lid). The four
# tubes (18 mm glass) stand in a row across the board's middle on a 32 mm pitch, centred;
# the lid gets a 19 mm hole over each tube and two 4 mm holes for the colon neons midway
# between tubes 2 and 3, 10 mm apart, centred on the row. The back gets the DC barrel jack
# (opening 10 wide x 11 high, centred 20 mm from the board's left end) and two right-angle
# set buttons (7 x 5 mm openings at 120 and 140 mm). No vents. "NIXIE" engraved in the
# middle of the front, 8 mm strokes.

import "std/enclosures.aidl"

thickness 3 mm

assembly clock_case {
    k = board_enclosure(width=160 mm, height=50 mm, depth=35 mm, thickness=3 mm,
                        clearance=2 mm,
                        holes=[[4, 4], [156, 4], [4, 46], [156, 46]], hole_d=3.2 mm,
                        standoff=5 mm,
                        ports=[["back", 20, 10, 11], ["back", 120, 7, 5], ["back", 140, 7, 5]],
                        vent="none", finger=10 mm)

    # tube holes and colon dots, centred on the lid
    hole tubes {
        for i in range(4) {
            c = Circle(center=((i - 1.5) * 32 mm, 0), diameter=19 mm)
        }
        d1 = Circle(center=(0, 5 mm), diameter=4 mm)
        d2 = Circle(center=(0, -5 mm), diameter=4 mm)
    }
    CenterInside(tubes, k.lid)
    CutInto(tubes, k.lid)

    drawing label {
        t = Text("NIXIE", position=(0, 0), size=8, valign="middle")
    }
    CenterInside(label, k.front)
    CutInto(label, k.front)

    # the request's numbers
    assert k.length == 160 mm + 2 * 2 mm + 2 * 3 mm, "outer length: board, clearance, walls"
    assert k.tall == 35 mm + 2 * 3 mm, "outer height: 35 inside plus floor and lid"
    assert len(tubes.c) == 4, "four tubes"
    assert tubes.c[1].center.x - tubes.c[0].center.x == 32 mm, "32 mm pitch"
    assert tubes.c[0].diameter == 19 mm, "19 mm tube holes"
    assert tubes.d1.center.y - tubes.d2.center.y == 10 mm, "colon dots 10 apart"
    assert tubes.bb.left >= k.lid.bb.left + 3 mm + 2 mm, "tube holes clear of the finger joints"
    assert tubes.bb.right <= k.lid.bb.right - 3 mm - 2 mm, "tube holes clear of the finger joints"
    assert distance(tubes.c[1], tubes.d1) >= 2 mm, "colon dots clear of the tube holes"
}
