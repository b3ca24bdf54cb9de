# Request (camping): a flat-pack camp kitchen shelf for the stove and the water jug, 9 mm
# ply, no glue and no screws. Two side frames 350 mm deep and 500 mm tall, top corners R20,
# standing on two 60 mm feet with an arch between them 60 mm high; a 110 x 32 mm carrying
# handle centred 45 mm below the top; a 230 x 170 mm window (R25) between the shelves to
# lighten them; "BASECAMP" engraved filled (20 mm, bold) on each side's outside, under the
# lower shelf. Two shelves 600 x 350 mm with R10 corners, at 150 mm and 400 mm (their middle
# planes), cross-halved into the sides: the sides' slots run in from the front half the depth
# (175 mm), the shelves' slots in from the back half the depth, 9.2 mm wide (0.2 mm
# clearance); the sides stand 40 mm in from the shelves' ends.

import "std/joints.aidl"

thickness 9 mm

t = 9 mm
gap = 0.2 mm
d = 350 mm
h = 500 mm
shelf_l = 600 mm
levels = [150 mm, 400 mm]
side_x = shelf_l / 2 - 40 mm

# s = 1: slots' mouths at -x (the right side, face "right"); s = -1: at +x (the left side)
def side_frame(s=1) -> solid {
    f = Line((-d / 2, 0), (-d / 2, h - 20 mm))
    tl = Arc(center=(-d / 2 + 20 mm, h - 20 mm), start=(-d / 2 + 20 mm, h), end=(-d / 2, h - 20 mm))
    top = Line((-d / 2 + 20 mm, h), (d / 2 - 20 mm, h))
    tr = Arc(center=(d / 2 - 20 mm, h - 20 mm), start=(d / 2, h - 20 mm), end=(d / 2 - 20 mm, h))
    b = Line((d / 2, h - 20 mm), (d / 2, 0))
    fb = Line((d / 2, 0), (d / 2 - 60 mm, 0))
    arch = Arc(start=(d / 2 - 60 mm, 0), through=(0, 60 mm), end=(-d / 2 + 60 mm, 0))
    ff = Line((-d / 2 + 60 mm, 0), (-d / 2, 0))
    for lv in levels {
        slot = cross_halving(depth=d / 2, thickness=t, clearance=gap, rotation=s * 90 deg,
                             cx=-s * d / 2, cy=lv)
    }
    hole handle { g = Slot(center=(0, h - 45 mm), length=110, width=32) }
    hole window { w = RoundedRectangle(center=(0, (levels[0] + levels[1]) / 2), width=230,
                                       height=170, corner_radius=25) }
    drawing name {
        n = Text("BASECAMP", position=(0, 100 mm), size=20, font="sans:Bold", valign="middle",
                 fill=true)
    }
    Fixed(f)
    Fixed(b)
    Fixed(top)
    Fixed(fb)
    Fixed(ff)
    assert slot[0].cut.bb.width > 174.9 mm and slot[0].cut.bb.width < 175.1 mm, "half the depth"
    assert slot[0].cut.bb.height > 9.19 mm and slot[0].cut.bb.height < 9.21 mm, "9.2 wide"
    assert window.bb.bottom - slot[0].cut.bb.top > 20 mm and slot[1].cut.bb.bottom - window.bb.top > 20 mm
    assert name.bb.top < slot[0].cut.bb.bottom and name.bb.bottom > 60 mm, "under the lower shelf"
}

def shelf() -> solid {
    board = RoundedRectangle(center=(0, 0), width=shelf_l, height=d, corner_radius=10)
    sl = cross_halving(depth=d / 2, thickness=t, clearance=gap, cx=-side_x, cy=d / 2)
    sr = cross_halving(depth=d / 2, thickness=t, clearance=gap, cx=side_x, cy=d / 2)
    Fixed(board)
    assert board.bb.right - sr.cut.bb.center_x == 40 mm, "sides 40 mm in"
}

assembly camp_shelf {
    left = side_frame(s=-1)
    right = side_frame(s=1)
    lower = shelf()
    upper = shelf()

    assert right.bb.width == 350 mm and right.bb.height == 500 mm
    assert lower.bb.width == 600 mm and lower.bb.height == 350 mm
    assert right.slot[0].cut.bb.width + lower.sr.cut.bb.height == 350 mm, "halvings meet"

    # flat on the sheet
    RightOf(right, left, gap=8)
    AlignBottom(right, left)
    Above(lower, left, gap=8)
    AlignLeft(lower, left)
    Above(upper, lower, gap=8)
    AlignLeft(upper, lower)

    # assembled: sides facing out, shelves at their levels
    Place(left, position=(-side_x + t / 2, 0, 0), face="left", up="up")
    Place(right, position=(side_x - t / 2, 0, 0), face="right", up="up")
    Place(lower, position=(0, 0, levels[0] - t / 2), face="up", up="back")
    Place(upper, position=(0, 0, levels[1] - t / 2), face="up", up="back")
}
