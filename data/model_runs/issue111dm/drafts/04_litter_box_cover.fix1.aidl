# Request (pets): a cover that stands over a cat's litter tray (trays up to 480 x 360 mm),
# in 6 mm poplar ply, finger-jointed (25 mm fingers), no bottom. Outside 500 wide, 380 deep,
# 360 tall: a front, a back, two sides and a top. The front has a cat-head doorway (an oval
# head 200 wide and 180 tall whose bottom is 70 mm above the floor, two pointed ears rising
# 45 mm above it, every corner of the opening rounded R6). The back has 32 vent holes of
# 12 mm in four staggered rows of eight at 40 mm pitch, the top row 60 mm below the top.
# Each side has a 110 x 30 mm hand hole, its middle 50 mm below the top. The top is
# engraved filled with the cat's name "MISO" (40 mm letters) and a paw print beside it.

import "std/joints.aidl"

thickness 6 mm
t = 6 mm

param W = 500 mm, min = 420 mm, max = 560 mm
param D = 380 mm, min = 320 mm, max = 390 mm
param H = 360 mm, min = 300 mm, max = 390 mm
fing = 25 mm

def wall(width=100 mm, doorway=false, vents=false) -> solid {
    p = finger_panel(width=width, height=H, thickness=t, finger=fing,
                     left="fingers", right="fingers", top="fingers", bottom="flat")
    if doorway {
        hole door {
            # head centre 70 + 90 mm above the floor (the panel's bottom is at -H/2)
            head = Ellipse(center=(0, -H / 2 + 160 mm), rx=100, ry=90)
            # FIX after the first valid program (W0405): the Fillet rounded the sharp ear tips
            # 8.7 mm down; the tips are now drawn round (R6 circles topping out 45 mm up)
            ear_l = Hull(Circle(center=(-80, -H / 2 + 289 mm), radius=6),
                         Point(-98, -H / 2 + 170 mm), Point(-35, -H / 2 + 238 mm))
            ear_r = Hull(Circle(center=(80, -H / 2 + 289 mm), radius=6),
                         Point(98, -H / 2 + 170 mm), Point(35, -H / 2 + 238 mm))
            Fillet(6 mm)
        }
    }
    if vents {
        hole vent { c = Circle(center=(-150, H / 2 - 60 mm), diameter=12) }
        grid = GridPattern(vent, rows=4, cols=8, col_spacing=40 mm, row_spacing=-40 mm, stagger=true)
    }
}

def side() -> solid {
    p = finger_panel(width=D, height=H, thickness=t, finger=fing,
                     left="slots", right="slots", top="fingers", bottom="flat")
    hole grip { s = Slot(center=(0, H / 2 - 50 mm), length=110, width=30) }
}

assembly litter_cover {
    front = wall(width=W, doorway=true)
    back = wall(width=W, vents=true)
    left = side()
    right = side()

    solid top {
        p = finger_panel(width=W, height=D, thickness=t, finger=fing,
                         left="slots", right="slots", top="slots", bottom="slots")
        drawing name {
            word = Text("MISO", position=(-40, 0), size=40, font="sans:Bold", valign="middle",
                        fill=true)
            pad = Ellipse(center=(120, -12), rx=22, ry=18, fill=true)
            for i in range(4) {
                toe = Circle(center=(120 + 34 * cos(150 deg - i * 40 deg), 22 + 10 * sin(150 deg - i * 40 deg)),
                             radius=8, fill=true)
            }
        }
    }

    # flat, side by side on the sheet
    RightOf(back, front, gap=10)
    AlignBottom(back, front)
    Above(top, front, gap=10)
    AlignLeft(top, front)
    RightOf(left, top, gap=10)
    AlignBottom(left, top)
    RightOf(right, left, gap=10)
    AlignBottom(right, left)

    # in 3D, standing over the tray
    Place(front, position=(0, -D / 2 + t, H / 2), face="front", up="up")
    Place(back, position=(0, D / 2 - t, H / 2), face="back", up="up")
    Place(right, position=(W / 2 - t, 0, H / 2), face="right", up="up")
    Place(left, position=(-W / 2 + t, 0, H / 2), face="left", up="up")
    Place(top, position=(0, 0, H - t), face="up", up="back")

    # the request's numbers
    assert front.p.outline.width == 500 mm and left.p.outline.width == 380 mm
    assert front.p.outline.height == 360 mm
    assert front.door.head.bb.bottom - front.p.outline.bb.bottom == 70 mm
    assert front.door.head.bb.width == 200 mm and front.door.head.bb.height == 180 mm
    assert front.door.bb.top - front.door.head.bb.top == 45 mm
    assert len(back.grid) == 32
    assert back.p.outline.bb.top - back.vent.c.center.y == 60 mm
    assert left.p.outline.bb.top - left.grip.s.center.y == 50 mm
}
