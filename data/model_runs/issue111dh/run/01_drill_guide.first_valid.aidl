# Request (workshop): a hand-drill guide block for drilling square to the surface.
# Three layers of 6 mm birch ply stacked into an 18 mm block, each 140 x 50 mm with R3 corners.
# Six guide holes 3, 4, 5, 6, 8 and 10 mm in one row, 18 mm apart, the row centred on the
# block's length and 6 mm above (behind) its centre line. On the front and back long edges of
# every layer a 90 degree sighting V-notch 3 mm deep lines up with each hole, to set the block
# on a pencil cross. Two M4 bolts hold the stack, 62 mm each side of the centre on the centre
# line: countersunk (9 mm head) in the top layer, 4.5 mm clearance in the middle one, an M4 nut
# trap in the bottom one. The top layer has each size engraved 5 mm tall, 12 mm in front of its
# hole (centre to centre), and "DRILL GUIDE" engraved 4 mm tall along the front.

units mm
thickness 6 mm

import "std/fasteners.aidl"

sizes = [3, 4, 5, 6, 8, 10]
pitch = 18 mm
row_y = 6 mm
block_w = 140 mm
block_h = 50 mm
bolt_x = 62 mm
notch = 3 mm

def guide_layer(kind="middle") -> solid {
    body = RoundedRectangle(center=(0, 0), width=block_w, height=block_h, corner_radius=3)
    for i in range(len(sizes)) {
        hole g { c = Circle(center=((i - 2.5) * pitch, row_y), diameter=sizes[i]) }
        # sighting V-notches, 90 degrees, 3 mm deep, front and back
        hole vf { v = Polygon([((i - 2.5) * pitch - notch - 1, -block_h / 2 - 1),
                               ((i - 2.5) * pitch + notch + 1, -block_h / 2 - 1),
                               ((i - 2.5) * pitch, -block_h / 2 + notch)]) }
        hole vb { v = Polygon([((i - 2.5) * pitch - notch - 1, block_h / 2 + 1),
                               ((i - 2.5) * pitch, block_h / 2 - notch),
                               ((i - 2.5) * pitch + notch + 1, block_h / 2 + 1)]) }
    }
    if kind == "bottom" {
        nl = nut_trap(size=4, cx=-bolt_x, cy=0)
        nr = nut_trap(size=4, cx=bolt_x, cy=0)
    } else {
        for s in [-1, 1] {
            hole bolt { c = Circle(center=(s * bolt_x, 0), diameter=4.5) }
        }
        if kind == "top" {
            Countersink(bolt, diameter=9)
        }
    }
    if kind == "top" {
        drawing labels {
            for i in range(len(sizes)) {
                t = Text(str(sizes[i]), position=((i - 2.5) * pitch, row_y - 12), size=5,
                         valign="middle")
            }
            title = Text("DRILL GUIDE", position=(0, -17), size=4, valign="middle")
        }
    }
}

assembly drill_guide {
    top = guide_layer(kind="top")
    middle = guide_layer(kind="middle")
    bottom = guide_layer(kind="bottom")

    # flat on the sheet: one above the other, 5 mm apart
    Above(middle, bottom, gap=5)
    Above(top, middle, gap=5)
    AlignCenterX(middle, bottom)
    AlignCenterX(top, bottom)

    # stacked in 3D
    Place(bottom, position=(0, 0, 0))
    Place(middle, position=(0, 0, 6))
    Place(top, position=(0, 0, 12))

    # the request's numbers
    assert top.body.bb.width == 140 mm, "block 140 long"
    assert top.body.bb.height == 50 mm, "block 50 deep"
    assert len(top.g) == 6, "six guide holes"
    assert top.g[0].c.diameter == 3 mm and top.g[5].c.diameter == 10 mm, "3 to 10 mm"
    assert top.g[1].c.center.x - top.g[0].c.center.x == 18 mm, "18 mm apart"
    assert top.g[5].c.center.x - top.g[0].c.center.x == 5 * 18 mm, "even row"
    assert (top.g[0].c.center.x + top.g[5].c.center.x) / 2 == top.body.center.x, "row centred"
    assert top.g[0].c.center.y - top.body.center.y == 6 mm, "row 6 behind the centre line"
    assert top.bolt[1].c.center.x - top.body.center.x == 62 mm, "bolt 62 from centre"
    assert top.labels.t[2].position.y - top.g[2].c.center.y == -12 mm, "label 12 in front"
}
