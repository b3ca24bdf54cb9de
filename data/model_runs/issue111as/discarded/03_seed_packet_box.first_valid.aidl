# Request (garden): a seed packet box in 3 mm ply, filed like a recipe box. An open-topped
# finger-jointed box 140 mm wide x 220 mm deep x 80 mm tall outside (10 mm fingers). The front
# has a finger scoop, a half circle of 25 mm radius centred on the middle of its top edge, and
# "SEEDS" engraved as filled bold letters 16 mm tall, centred 28 mm above its bottom edge.
# Four index cards stand in the box across its width: each card is 130 mm wide (2 mm play each
# side of the 134 mm inside) and 95 mm tall with 3 mm rounded top corners, plus a 40 x 14 mm
# tab on top (4 mm rounded top corners). The tabs are staggered from left to right, tab k
# (k = 0..3) centred 45 - 30 k mm left of the card's centre... i.e. -45, -15, 15, 45 mm, and
# they carry "SPRING", "SUMMER", "AUTUMN", "WINTER" engraved 6 mm tall (single stroke).

import "std/joints.aidl"

thickness 3 mm

mat = 3 mm
param box_w = 140 mm, min = 110 mm, max = 200 mm
param box_d = 220 mm, min = 120 mm, max = 320 mm
param box_h = 80 mm, min = 50 mm, max = 120 mm
card_w = 130 mm
card_h = 95 mm
tab_w = 40 mm
tab_h = 14 mm

def card(name="SPRING", k=0) -> solid {
    body = RoundedRectangle(center=(0, card_h / 2), width=card_w, height=card_h,
                            corner_radii=[3, 3, 0, 0])
    # the tab overlaps the card by 1 mm so the two merge into one outline
    tab = RoundedRectangle(center=((k * 30 - 45) * 1 mm, card_h + tab_h / 2 - 0.5 mm),
                           width=tab_w, height=tab_h + 1 mm, corner_radii=[4, 4, 0, 0])
    drawing label {
        t = Text(name, position=((k * 30 - 45) * 1 mm, card_h + tab_h / 2), size=6,
                 valign="middle", max_width=tab_w - 6 mm)
    }
}

assembly seed_box {
    box = finger_box(length=box_w, depth=box_d, height=box_h, thickness=mat, finger=10 mm,
                     closed=false)
    hole scoop {
        c = Circle(center=(0, 0), radius=25)
    }
    scoop.c.center == box.front.outline.top.midpoint
    CutInto(scoop, box.front)
    drawing word {
        w = Text("SEEDS", position=(0, 0), size=16, font="sans:Bold", valign="middle", fill=true)
    }
    w_pos = word.w.position
    word.w.position == (box.front.outline.bb.center_x, box.front.outline.bb.bottom + 28 mm)
    CutInto(word, box.front)

    spring = card(name="SPRING", k=0)
    summer = card(name="SUMMER", k=1)
    autumn = card(name="AUTUMN", k=2)
    winter = card(name="WINTER", k=3)
    RightOf(spring, box, gap=10)
    AlignBottom(spring, box)
    Above(summer, spring, gap=5)
    AlignLeft(summer, spring)
    RightOf(autumn, spring, gap=5)
    AlignBottom(autumn, spring)
    Above(winter, autumn, gap=5)
    AlignLeft(winter, autumn)

    # the request's numbers
    assert box.front.outline.bb.width == 140 mm, "140 mm wide outside"
    assert box.left.outline.bb.height == 220 mm, "220 mm deep outside"
    assert box.front.outline.bb.height == 80 mm, "80 mm tall outside"
    assert scoop.c.radius == 25 mm, "scoop radius 25"
    assert word.w.size == 16 mm, "SEEDS 16 mm tall"
    assert 140 mm - 2 * mat - spring.body.bb.width == 4 mm, "2 mm play each side of the card"
    assert spring.body.bb.height == 95 mm and spring.body.bb.width == 130 mm, "cards 130 x 95"
    assert abs(spring.tab.bb.center_x - spring.body.bb.center_x + 45 mm) < 0.01 mm, "first tab at -45"
    assert abs(winter.tab.bb.center_x - winter.body.bb.center_x - 45 mm) < 0.01 mm, "last tab at +45"
    assert abs(winter.tab.bb.right - winter.body.bb.right) < 0.01 mm, "last tab flush with the right edge"
    assert abs(spring.tab.bb.top - spring.body.bb.top - 14 mm) < 0.01 mm, "tab 14 mm above the card"
    assert spring.body.bb.height > box_h - mat, "cards stand proud of the rim"
}
