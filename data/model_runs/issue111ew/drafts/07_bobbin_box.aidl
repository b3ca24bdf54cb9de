# Request (crafts): a box for sewing-machine bobbins (class 15: 20.5 mm across, 11.7 mm
# tall), 3 mm birch ply. A finger-jointed box with a lift-off lid, 130 x 100 x 30 mm
# outside (fingers at least 10 mm, 0.3 mm lid clearance). "BOBBINS" engraved in filled
# bold letters 10 mm high in the middle of the lid. Inside, a rack insert lying on the
# floor: the inside size less 0.5 mm all round, twelve 21.5 mm bobbin holes in 3 rows of 4
# on 27 mm centres, centred, and a 14 mm round finger notch in the middle of each short
# edge, with at least 3 mm of wood between a notch and a bobbin hole.

import "std/boxes.aidl"

units mm
thickness 3 mm

assembly bobbin_box {
    box = lid_box(length=130 mm, width=100 mm, height=30 mm, thickness=3 mm, finger=10 mm,
                  clearance=0.3 mm)

    drawing label {
        t = Text("BOBBINS", position=(0, 0), size=10, font="sans:Bold", valign="middle",
                 fill=true)
    }
    CenterInside(label, box.lid)
    CutInto(label, box.lid)

    solid insert {
        body = Rectangle(center=(0, 0), width=130 - 2 * 3 - 1, height=100 - 2 * 3 - 1)
        hole bobbin { c = Circle(center=(-40.5, -27), diameter=21.5) }
        holes = GridPattern(bobbin, 3, 4, 27)
        hole notches {
            l = Circle(center=(-61.5, 0), diameter=14)
            r = Circle(center=(61.5, 0), diameter=14)
        }
    }

    # on the sheet: the insert beside the box's parts
    RightOf(insert, box, gap=5)
    AlignTop(insert, box)

    # in the box, on its floor
    Place(insert, position=(0, 0, 3), face="up")

    assert box.length == 130 mm and box.width == 100 mm and box.height == 30 mm
    assert insert.body.width == 130 mm - 2 * 3 mm - 2 * 0.5 mm, "inside less 0.5 all round"
    assert insert.body.height == 100 mm - 2 * 3 mm - 2 * 0.5 mm
    assert len(insert.holes) == 12 and insert.bobbin.c.diameter == 21.5 mm
    assert distance(insert.holes[0].c.center, insert.holes[1].c.center) == 27 mm
    assert distance(insert.holes[0].c.center, insert.holes[4].c.center) == 27 mm
    assert abs((insert.holes[0].bb.left + insert.holes[11].bb.right) / 2 -
               insert.body.bb.center_x) < 0.01 mm, "grid centred across"
    assert abs((insert.holes[0].bb.bottom + insert.holes[11].bb.top) / 2 -
               insert.body.bb.center_y) < 0.01 mm, "grid centred up"
    assert insert.notches.l.diameter == 14 mm
    assert distance(insert.notches, insert.holes) >= 3 mm, "3 mm wood by the notches"
    assert label.t.size == 10 mm and label.bb.width <= box.lid.bb.width - 20 mm
}
