# Request: a caddy for the sewing table that keeps four pairs of scissors standing points
# down, plus a seam ripper and a marking pen: a closed finger-jointed box 180 long x 70 deep x
# 100 tall (outside) from 4 mm ply, fingers 12 mm. In its top: four blade slots 6 x 28 mm
# running front to back, 25 mm apart, the first 65 mm left of the centre, and two 13 mm
# round holes at 40 and 65 mm right of the centre, all on the top's centre line. "SEWING ROOM"
# engraved on the front, 9 mm letters along an arc of radius 55 over the top, the letters'
# top 20 mm below the front's top edge.

import "std/joints.aidl"

thickness 4 mm

assembly scissor_caddy {
    box = finger_box(length=180 mm, depth=70 mm, height=100 mm, thickness=4 mm,
                     finger=12 mm, closed=true, gap=8 mm)

    hole tools {
        for i in range(4) {
            s = Slot(center=(-65 + 25 * i, 0), length=28, width=6, rotation=90 deg)
        }
        for x in [40, 65] {
            p = Circle(center=(x, 0), diameter=13)
        }
    }
    AlignCenterY(tools, box.lid)
    tools.s[0].center.x == box.lid.bb.center_x - 65 mm
    CutInto(tools, box.lid)

    # FIX after the first valid program: std text_on_arc set the letters a fixed pitch apart,
    # so the narrow I stood in wide gaps ("SEW I NG"); Text along= a circle spaces them as the
    # straight text does
    drawing label {
        ring = Circle(center=(0, 0), radius=55, construction=true)
        w = Text("SEWING ROOM", along=ring, size=9)
    }
    AlignCenterX(label, box.front)
    label.bb.top == box.front.bb.top - 20 mm
    CutInto(label, box.front)

    assert box.front.bb.width == 180 mm and box.front.bb.height == 100 mm, "180 x 100"
    assert box.left.bb.height == 70 mm, "70 deep"
    assert len(tools.s) == 4 and len(tools.p) == 2, "four slots, two holes"
    assert tools.s[1].center.x - tools.s[0].center.x == 25 mm, "slots 25 apart"
    assert tools.s[0].length == 28 mm and tools.s[0].width == 6 mm, "slots 6 x 28"
    assert tools.p[0].center.x - box.lid.bb.center_x == 40 mm, "pen hole 40 right"
    assert tools.p[1].center.x - box.lid.bb.center_x == 65 mm, "pen hole 65 right"
}
