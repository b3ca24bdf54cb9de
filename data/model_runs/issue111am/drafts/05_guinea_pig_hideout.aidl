# Request (pets): a guinea-pig hideout in 6 mm ply, open bottom, no roof panel (the roof is
# a towel). Two gable ends: 200 mm wide, walls 120 mm, apex 170 mm high. The front has a
# round-topped doorway 90 wide x 90 tall from the floor and "PIP & POP" engraved (bold, 12 mm,
# filled) between door and apex; the back a 50 mm round window 75 mm up. Two side walls
# 250 x 120 mm, each with three 30 mm round windows 60 mm apart at mid height, glued into the
# gable ends by two 30 mm tenons at each end into mortises 13 mm in from each gable's sides.
units mm
thickness 6 mm
import "std/joints.aidl"

def gable(x0=0 mm) -> solid {
    body = Polygon([(-100, 0), (100, 0), (100, 120), (0, 170), (-100, 120)])
    ml = tab_and_slot(part="slot", length=120 mm, thickness=6 mm, tabs=2, tab=30 mm, screw=0,
                      rotation=90 deg, cx=-87 mm, cy=60 mm)
    mr = tab_and_slot(part="slot", length=120 mm, thickness=6 mm, tabs=2, tab=30 mm, screw=0,
                      rotation=90 deg, cx=87 mm, cy=60 mm)
}

def side() -> solid {
    wall = Rectangle(center=(0, 0), width=250, height=120)
    tl = tab_and_slot(part="tab", length=120 mm, thickness=6 mm, tabs=2, tab=30 mm, screw=0,
                      rotation=90 deg, cx=-125 mm, cy=0 mm)
    tr = tab_and_slot(part="tab", length=120 mm, thickness=6 mm, tabs=2, tab=30 mm, screw=0,
                      rotation=-90 deg, cx=125 mm, cy=0 mm)
    hole win {
        w = Circle(center=(-60, 0), diameter=30)
    }
    ws = LinearPattern(win, 3, (60, 0))
}

assembly hideout {
    front = gable()
    hole door {
        r = Rectangle(corner=(-45, -1), opposite=(45, 45), overrun=true)
        c = Circle(center=(0, 45), radius=45)
    }
    CutInto(door, front)
    drawing name {
        t = Text("PIP & POP", (0, 130), size=12, font="sans:Bold", fill=true, valign="middle")
    }
    CutInto(name, front)
    back = gable()
    hole window {
        c = Circle(center=(0, 75), diameter=50)
    }
    CutInto(window, back)
    RightOf(back, front, gap=20)
    left = side()
    right = side()
    Below(left, front, gap=20)
    AlignLeft(left, front)
    RightOf(right, left, gap=20)
    AlignCenterY(right, left)
    Concentric(window.c.center, polar(back.body.points[0], 0, 0 deg) + (100, 75))
    assert front.body.bb.width == 200 mm and front.body.bb.height == 170 mm, "gable size"
    assert door.bb.height == 90 mm and door.bb.width == 90 mm, "doorway 90 x 90"
    assert left.wall.width == 250 mm and left.wall.height == 120 mm, "side wall size"
    assert len(left.ws) == 3, "three windows"
    assert name.bb.bottom > door.bb.top + 3, "name clear of the door"
}
