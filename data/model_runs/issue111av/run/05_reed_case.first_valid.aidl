# Request: A case for my B-flat clarinet reeds, from 3 mm plywood: a finger-jointed box with a
# sliding lid, 94 x 81 mm inside and 8 mm deep under the lid (6 mm fingers), the lid engraved
# "CLARINET REEDS" in 7 mm letters across its middle. A loose insert, 93 x 80 mm, lies on the
# box's floor and holds five reeds flat: five through pockets, each 15 x 72 mm, 3 mm ribs
# between them, centred on the insert; pocket corners rounded 2 mm so a reed's tip is not
# scuffed. Lay it all out for cutting.

units mm
thickness 3 mm

import "std/boxes.aidl"

param ply = 3 mm, min = 3 mm, max = 4 mm
param pockets = 5, min = 3, max = 6

POCKET_W = 15 mm
POCKET_L = 72 mm
RIB = 3 mm

assembly reed_case {
    box = sliding_lid_box(length=94 mm, width=81 mm, height=8 mm, thickness=ply, finger=6 mm,
                          outside=false)
    drawing title {
        t = Text("CLARINET REEDS", position=(0, 0), size=7, valign="middle")
    }
    CenterInside(title, box.lid)
    CutInto(title, box.lid)

    solid insert {
        plate = Rectangle(center=(0, 0), width=93, height=80)
        hole pocket {
            p = RoundedRectangle(center=(0, 0), width=POCKET_W, height=POCKET_L, corner_radius=2)
        }
        row = LinearPattern(pocket, pockets, (POCKET_W + RIB, 0))
        # the row of pockets centred on the plate
        (row[0].bb.left + row[pockets - 1].bb.right) / 2 == plate.center.x
        AlignCenterY(pocket, plate)
    }
    RightOf(insert, box, gap=10)
    AlignBottom(insert, box)

    assert len(insert.row) == 5, "five pockets"
    assert abs(insert.plate.width - 93 mm) < 0.001 mm and abs(insert.plate.height - 80 mm) < 0.001 mm,
        "insert 93 x 80"
    assert abs(insert.pocket.p.width - 15 mm) < 0.001 mm and abs(insert.pocket.p.height - 72 mm) < 0.001 mm,
        "pockets 15 x 72"
    assert abs(insert.row[1].bb.left - insert.row[0].bb.right - 3 mm) < 0.001 mm, "3 mm ribs"
    assert abs(insert.row[0].bb.left - insert.plate.bb.left - (insert.plate.bb.right - insert.row[4].bb.right)) < 0.001 mm,
        "pockets centred across the insert"
    assert insert.plate.width <= 94 mm and insert.plate.height <= 81 mm, "insert fits inside the box"
    assert title.bb.width < box.lid.bb.width - 10 mm, "title fits the lid"
}
