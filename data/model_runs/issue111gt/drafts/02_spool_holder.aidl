# Request (electronics / 3D printing): a holder for 1 kg filament spools (200 mm across,
# 65 mm wide, 53 mm hub hole), from 6 mm ply.
# - An 8 mm steel rod runs through the spool and rests in two 608 bearings (22 mm outside)
#   pressed into 22 mm bores in two uprights.
# - Each upright is 120 mm wide at the base's top face and rises to a round top 50 mm across,
#   centred on the bearing bore 130 mm above the base's top face; each stands in the base on
#   two 30 mm glued tenons. The uprights' inside faces are 90 mm apart.
# - Base 180 x 140 mm, 8 mm corners, four M4 countersunk screw holes (9 mm heads) 12 mm in
#   from the edges, "PLA 1.75" engraved (10 mm) between the uprights.
# - On the rod, each side of the spool: a 52 mm hub disc that sits in the spool's hole and a
#   70 mm flange disc outside it, both with an 8.2 mm bore, glued together.

import "std/joints.aidl"
import "std/plates.aidl"

t = 6 mm
thickness t

# drawn with the base's top face at y = 0; the tenons reach down to y = -6
def upright() -> solid {
    top = Circle(center=(0, 130), diameter=50)
    foot = Hull(top, Point(-60, 0), Point(60, 0))
    strip = Rectangle(center=(0, -3), width=120, height=6)
    tenons = tab_and_slot(part="tab", length=120 mm, thickness=t, tabs=2, tab=30 mm, screw=0,
                          rotation=180 deg, cx=0 mm, cy=-6 mm)
    hole bore { c = Circle(center=(0, 130), diameter=22) }
}

def disc(d=52 mm) -> solid {
    c = Circle(center=(0, 0), diameter=d)
    hole bore { b = Circle(center=(0, 0), diameter=8.2) }
}

assembly spool_holder {
    solid base {
        p = mounting_plate(width=180 mm, height=140 mm, corner_radius=8 mm, screw=4, inset=12 mm)
        Countersink(p.corner, diameter=9 mm)
        for i in range(2) {
            ms = tab_and_slot(part="slot", length=120 mm, thickness=t, tabs=2, tab=30 mm,
                              screw=0, cx=0 mm, cy=(2 * i - 1) * 48 mm)
        }
        drawing label {
            word = Text("PLA 1.75", position=(0, 0), size=10, valign="middle")
        }
    }

    for i in range(2) {
        side = upright()
        hub = disc(d=52 mm)
        flange = disc(d=70 mm)
    }

    # 3D: the base on the table, the uprights at y = -48 and 48 (inside faces 90 apart),
    # the rod 130 above the base's top face, the spool's faces at y = -32.5 and 32.5
    Place(base, position=(0, 0, 0))
    Place(side[0], position=(0, -45 mm, t), face="front", up="up")
    Place(side[1], position=(0, 51 mm, t), face="front", up="up")
    Place(hub[0], position=(0, -26.5 mm, 136 mm), face="front", up="up")
    Place(flange[0], position=(0, -32.5 mm, 136 mm), face="front", up="up")
    Place(hub[1], position=(0, 32.5 mm, 136 mm), face="front", up="up")
    Place(flange[1], position=(0, 38.5 mm, 136 mm), face="front", up="up")

    # flat layout for cutting
    RightOf(side[1], side[0], gap=6 mm)
    AlignBottom(side[1], side[0])
    Below(base, side[0], gap=6 mm)
    AlignLeft(base, side[0])
    RightOf(hub[0], base, gap=6 mm)
    AlignTop(hub[0], base)
    RightOf(hub[1], hub[0], gap=6 mm)
    AlignTop(hub[1], hub[0])
    Below(flange[0], hub[0], gap=6 mm)
    AlignLeft(flange[0], hub[0])
    RightOf(flange[1], flange[0], gap=6 mm)
    AlignTop(flange[1], flange[0])

    # the request's numbers
    assert side[0].foot.bb.width == 120 mm, "uprights 120 wide at the base"
    assert side[0].top.diameter == 50 mm, "round top 50 across"
    assert side[0].bore.c.diameter == 22 mm, "608 bearing bore"
    assert side[0].bore.c.center.y - side[0].foot.bb.bottom == 130 mm, "bearing 130 above the base"
    assert side[0].bore.c.center.y - side[0].foot.bb.bottom > 200 mm / 2, "the spool clears the base"
    assert base.ms[1].slot[0].bb.center_y - base.ms[0].slot[0].bb.center_y == 90 mm + t,
        "inside faces 90 apart"
    assert len(base.ms[0].slot) == 2 and base.ms[0].slot[0].bb.width == 30 mm, "two 30 mm tenons"
    assert base.p.body.width == 180 mm and base.p.body.height == 140 mm, "base 180 x 140"
    assert base.p.corner[0].c.center.x - base.p.body.bb.left == 12 mm, "screws 12 in"
    assert base.p.corner[0].c.center.y - base.p.body.bb.bottom == 12 mm, "screws 12 in"
    assert hub[0].c.diameter < 53 mm and flange[0].c.diameter > 53 mm, "hub in the hole, flange outside"
    assert 65 mm + 2 * t < 90 mm, "spool and flanges fit between the uprights"
    assert distance(base.label, base.ms) >= 5 mm, "label clear of the mortises"
}
