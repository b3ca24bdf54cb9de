# Request (bathroom): a small leaning ladder for guest hand towels, 6 mm birch ply, glued:
# two 40 x 450 mm uprights with a rounded (semicircular) top; three rungs 30 mm deep, 288 mm
# between the uprights, each with a 20 mm wide tenon 6 mm long at both ends through a mortise
# in each upright (0.1 mm clearance); rungs 120, 240 and 360 mm above the floor (their
# underside). The top rung has "towels" engraved filled in a serif font, 12 mm high.

units mm
thickness 6 mm

import "std/joints.aidl"

t = 6 mm
inner = 288 mm
rung_len = inner + 2 * t
rung_d = 30 mm
tenon = 20 mm
up_w = 40 mm
up_h = 450 mm
first_h = 120 mm
step_h = 120 mm

def rung(labelled=false) -> solid {
    body = Rectangle(center=(0, 0), width=rung_len, height=rung_d)
    right_end = tab_and_slot(part="tab", length=rung_d, thickness=t, tabs=1, tab=tenon,
                             screw=0, rotation=-90 deg, cx=rung_len / 2, cy=0)
    left_end = tab_and_slot(part="tab", length=rung_d, thickness=t, tabs=1, tab=tenon,
                            screw=0, rotation=90 deg, cx=-rung_len / 2, cy=0)
    if labelled {
        drawing word {
            w = Text("towels", position=(0, 0), size=12, font="serif", valign="middle",
                     fill=true)
        }
    }
}

def upright() -> solid {
    body = RoundedRectangle(bottom_left=(-up_w / 2, 0), width=up_w, height=up_h,
                            corner_radii=[up_w / 2, up_w / 2, 0, 0])
    Fixed(body)
    for i in range(3) {
        m = tab_and_slot(part="slot", length=rung_d, thickness=t, tabs=1, tab=tenon, screw=0,
                         clearance=0.1, cx=0, cy=first_h + i * step_h + t / 2)
    }
}

assembly towel_ladder {
    left = upright()
    right = upright()
    low = rung()
    mid = rung()
    top = rung(labelled=true)

    # on the sheet: uprights side by side, rungs in a column beside them
    RightOf(right, left, gap=6)
    AlignBottom(right, left)
    RightOf(low, right, gap=6)
    RightOf(mid, right, gap=6)
    RightOf(top, right, gap=6)
    AlignBottom(low, left)
    Above(mid, low, gap=6)
    Above(top, mid, gap=6)

    # in 3D: uprights stand edge-on (height up z, depth along y, thickness along +x),
    # rungs lie flat with their tenons through the mortises
    Place(left, position=(-rung_len / 2, 0, 0), rotation=(90 deg, 0, 90 deg))
    Place(right, position=(rung_len / 2 - t, 0, 0), rotation=(90 deg, 0, 90 deg))
    Place(low, position=(0, 0, first_h))
    Place(mid, position=(0, 0, first_h + step_h))
    Place(top, position=(0, 0, first_h + 2 * step_h))

    assert left.body.bb.width == 40 mm and left.body.bb.height == 450 mm, "uprights 40 x 450"
    assert len(left.m) == 3, "three mortises per upright"
    assert left.m[0].bb.center_y - t / 2 - left.body.bb.bottom == 120 mm, "low rung 120 up"
    assert left.m[1].bb.center_y - left.m[0].bb.center_y == 120 mm, "rungs 120 apart"
    assert left.m[2].bb.center_y - t / 2 - left.body.bb.bottom == 360 mm, "top rung 360 up"
    assert left.m[0].bb.width == 20.1 mm and left.m[0].bb.height == 6.1 mm, "mortise 20 x 6 + 0.1"
    assert low.body.bb.height == 30 mm, "rungs 30 deep"
    assert low.body.bb.width - 2 * 6 mm == 288 mm, "288 between the uprights"
    assert top.word.w.size == 12 mm, "label 12 mm"
}
