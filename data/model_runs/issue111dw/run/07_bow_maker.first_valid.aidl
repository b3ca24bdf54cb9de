# Request (crafts): a ribbon bow maker in 6 mm plywood. A base 250 x 60 with R8 corners; two
# uprights 60 wide standing 70 mm above the base, each with a 4 mm ribbon slot 45 mm deep down
# from its top (round bottom, the mouth flared to 12 mm over 5 mm), each pressed into the base
# by one 30 mm tenon (0.2 mm clearance in the mortise). The base has a mortise pair for each bow
# width 50, 80, 110 and 140 mm (upright centre to centre, symmetric about the middle); each
# width engraved (single-stroke, 4 mm) beside its mortises on the back margin. An engraved
# scale on the front margin: a tick every 10 mm from the middle out to 120 mm each way, 3 mm
# long, every 50 mm 6 mm long.

import "std/joints.aidl"

thickness 6 mm
t = 6 mm

base_l = 250 mm
base_d = 60 mm
up_w = 60 mm
up_h = 70 mm
rib_w = 4 mm
rib_d = 45 mm
widths = [50, 80, 110, 140]

def upright() -> solid {
    # frame: y = 0 the base's top face, the tenon's tip at -t
    body = Rectangle(bottom_left=(-up_w / 2, -t), width=up_w, height=up_h + t)
    tenon = tab_and_slot(part="tab", length=up_w, thickness=t, tabs=1, tab=30 mm, screw=0,
                         rotation=180 deg, cx=0 mm, cy=-t)
    hole ribbon {
        s = Slot(start=(0, up_h - rib_d + rib_w / 2), end=(0, up_h + 2 mm), width=rib_w)
        flare = Polygon([(-6 mm, up_h + 1 mm), (6 mm, up_h + 1 mm), (rib_w / 2, up_h - 5 mm),
                         (-rib_w / 2, up_h - 5 mm)])
    }
}

assembly bow_maker {
    solid base {
        p = RoundedRectangle(center=(0, 0), width=base_l, height=base_d, corner_radius=8)
        for k in range(len(widths)) {
            ml = tab_and_slot(part="slot", length=up_w, thickness=t, tabs=1, tab=30 mm, screw=0,
                              clearance=0.2 mm, rotation=90 deg, cx=-widths[k] / 2 * 1 mm,
                              cy=0 mm)
            mr = tab_and_slot(part="slot", length=up_w, thickness=t, tabs=1, tab=30 mm, screw=0,
                              clearance=0.2 mm, rotation=90 deg, cx=widths[k] / 2 * 1 mm,
                              cy=0 mm)
        }
        drawing marks {
            for k in range(len(widths)) {
                nl = Text(str(widths[k]), position=(-widths[k] / 2 * 1 mm, 22 mm), size=4,
                          valign="middle")
                nr = Text(str(widths[k]), position=(widths[k] / 2 * 1 mm, 22 mm), size=4,
                          valign="middle")
            }
            for i in range(25) {
                tick = Line(start=((i - 12) * 10 mm, -base_d / 2 + 2 mm),
                            end=((i - 12) * 10 mm,
                                 -base_d / 2 + 2 mm + (6 mm if (i - 12) % 5 == 0 else 3 mm)))
            }
        }
    }

    left = upright()
    right = upright()

    # flat on the sheet
    Below(left, base, gap=8)
    AlignLeft(left, base)
    RightOf(right, left, gap=8)
    AlignBottom(right, left)

    # in 3D: set for a 110 mm bow
    Place(base, position=(0, 0, 0))
    Place(left, position=(-55 mm - t / 2, 0, t), face="right", up="up")
    Place(right, position=(55 mm - t / 2, 0, t), face="right", up="up")

    assert base.p.bb.width == 250 mm and base.p.bb.height == 60 mm, "base 250 x 60"
    assert left.body.bb.height - 6 mm == 70 mm and left.body.bb.width == 60 mm, "uprights 60 x 70"
    assert left.ribbon.s.width == 4 mm, "ribbon slot 4 wide"
    assert left.body.bb.top - left.ribbon.s.bb.bottom == 45 mm, "ribbon slot 45 deep"
    assert left.ribbon.flare.bb.width == 12 mm, "mouth flared to 12"
    assert len(base.ml) == 4, "four bow widths"
    assert base.mr[0].slot[0].bb.center_x - base.ml[0].slot[0].bb.center_x == 50 mm, "50 mm bow"
    assert base.mr[3].slot[0].bb.center_x - base.ml[3].slot[0].bb.center_x == 140 mm, "140 mm bow"
    assert base.ml[0].slot[0].bb.height == 30.2 mm, "30 mm tenon, 0.2 clearance"
    assert base.ml[0].slot[0].bb.left - base.ml[1].slot[0].bb.right >= 5 mm,
        "a web of 5 mm or more between neighbouring mortises"
    assert base.marks.tick[24].start.x - base.marks.tick[0].start.x == 240 mm, "ticks to 120 each way"
    assert base.marks.nr[2].bb.right <= base.marks.nr[3].bb.left - 1 mm, "width labels apart"
    assert base.marks.nr[0].bb.bottom >= base.ml[0].slot[0].bb.top + 1 mm, "labels off the mortises"
}
