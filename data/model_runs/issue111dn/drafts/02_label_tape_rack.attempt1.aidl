# Request: a desk caddy for my label printer's tape cassettes, 3 mm ply, finger-jointed. Six
# cassettes (88 x 68 x 18 mm) stand on their long edge side by side, each in its own
# compartment 22 mm wide inside (4 mm of play), behind 3 mm dividers. Inside the tray is 92 mm
# deep (88 + 4) and 40 mm tall, so 28 mm of each cassette stands out to grab. Each end wall
# has a 40 x 12 mm finger slot 12 mm below its top edge, to carry it. The front is engraved
# with each compartment's tape under it: WHT, YEL, CLR, RED, BLU, GRN (5 mm letters, 6 mm
# below the top edge), and the back with "LABEL TAPES 12 mm".

import "std/boxes.aidl"

thickness 3 mm

t = 3 mm
cells = 6
cell = 22 mm
tapes = ["WHT", "YEL", "CLR", "RED", "BLU", "GRN"]
inside_len = cells * cell + (cells - 1) * t
pitch = cell + t

assembly caddy {
    k = divider_tray(length=inside_len, width=92 mm, height=40 mm, rows=1, cols=cells,
                     thickness=t, finger=10 mm, outside=false)

    drawing front_labels {
        for i in range(cells) {
            tag = Text(tapes[i], position=((i - (cells - 1) / 2) * pitch, 0), size=5,
                       valign="top")
        }
    }
    # the labels' tops 6 mm under the front's top edge, compartment 0 at the left
    At(front_labels.tag[0].position, k.body.front.bb.center,
       dx=-(cells - 1) / 2 * pitch, dy=0)
    front_labels.tag[0].position.y == k.body.front.bb.top - t - 6 mm
    CutInto(front_labels, k.body.front)

    drawing back_title {
        name = Text("LABEL TAPES 12 mm", position=(0, 0), size=7, valign="middle")
    }
    CenterInside(back_title, k.body.back)
    CutInto(back_title, k.body.back)

    hole grip_l { s = Slot(center=(0, 0), length=40, width=12, rotation=90 deg) }
    hole grip_r { s = Slot(center=(0, 0), length=40, width=12, rotation=90 deg) }
    AlignCenterY(grip_l, k.body.left)
    AlignCenterY(grip_r, k.body.right)
    grip_l.s.center.x == k.body.left.bb.left + 12 mm
    grip_r.s.center.x == k.body.right.bb.right - 12 mm
    CutInto(grip_l, k.body.left)
    CutInto(grip_r, k.body.right)

    assert len(tapes) == 6, "six cassettes"
    assert (k.length - 5 * 3 mm) / 6 == 22 mm, "compartments 22 mm inside"
    assert k.width - 88 mm == 4 mm, "4 mm play across"
    assert k.height == 40 mm, "walls 40 mm tall inside"
    assert 68 mm - k.height == 28 mm, "28 mm of cassette stands out"
}
