# Request: a screen-printing frame for A4 prints and its squeegee, 6 mm birch ply.
# The frame: four bars 30 mm tall standing on edge, crossed at the corners with halving joints
# (the long bars slotted from the top, the short bars from the bottom, 15 mm each, so top and
# bottom edges are flush and the mesh can be stapled to the bottom); the opening between the
# bars' inner faces 360 x 260 mm; each bar runs on 15 mm past the crossing. The front long
# bar carries "A4 SCREEN - 120T MESH" engraved on its outer face, 8 mm letters.
# The squeegee: a handle plate 280 x 90 mm, its top corners R20, a 110 x 28 mm hand slot
# centred 55 mm up, and a clamp strip 280 x 30 mm; the 6 mm rubber blade is clamped between
# them at the bottom edge by four M5 bolts 70 mm apart, 15 mm up.

import "std/joints.aidl"
import "std/fasteners.aidl"

t = 6 mm
thickness t
H = 30 mm          # bar height
OPEN_X = 360 mm    # opening along the long bars
OPEN_Y = 260 mm    # opening along the short bars
RUN = 15 mm        # bar past the crossing

def bar(cross=OPEN_X + t, from_top=true) -> solid {
    # bottom edge on y = 0; crossings at x = -cross/2 and +cross/2 (the other bars' centre lines)
    body = Rectangle(center=(0, H / 2), width=cross + t + 2 * RUN, height=H)
    if from_top {
        h_l = cross_halving(depth=H / 2, thickness=t, rotation=0 deg, cx=-cross / 2, cy=H)
        h_r = cross_halving(depth=H / 2, thickness=t, rotation=0 deg, cx=cross / 2, cy=H)
    } else {
        h_l = cross_halving(depth=H / 2, thickness=t, rotation=180 deg, cx=-cross / 2, cy=0 mm)
        h_r = cross_halving(depth=H / 2, thickness=t, rotation=180 deg, cx=cross / 2, cy=0 mm)
    }
    Rigid(self)
}

def bolts() -> hole {
    for i in range(4) {
        b = Circle(center=(-105 + 70 * i, 15), diameter=5.5)
    }
}

assembly screen {
    front_bar = bar(cross=OPEN_X + t, from_top=true)
    back_bar = bar(cross=OPEN_X + t, from_top=true)
    left_bar = bar(cross=OPEN_Y + t, from_top=false)
    right_bar = bar(cross=OPEN_Y + t, from_top=false)

    drawing legend {
        w = Text("A4 SCREEN - 120T MESH", position=(0, 0), size=8, valign="middle")
    }
    AlignCenterX(legend, front_bar.body)
    AlignCenterY(legend, front_bar.body)
    CutInto(legend, front_bar)

    solid handle {
        body = RoundedRectangle(center=(0, 45), width=280, height=90, corner_radii=[20, 20, 0, 0])
        hole grip {
            s = Slot(center=(0, 55), length=110, width=28)
        }
        holes = bolts()
        Rigid(self)
    }
    solid strip {
        body = Rectangle(center=(0, 15), width=280, height=30)
        holes = bolts()
        Rigid(self)
    }

    # flat on the sheet: the bars in a column, the squeegee beside them
    Below(back_bar, front_bar, gap=8)
    AlignLeft(back_bar, front_bar)
    Below(left_bar, back_bar, gap=8)
    AlignLeft(left_bar, back_bar)
    Below(right_bar, left_bar, gap=8)
    AlignLeft(right_bar, left_bar)
    Below(handle, right_bar, gap=8)
    AlignLeft(handle, right_bar)
    RightOf(strip, handle, gap=8)
    AlignBottom(strip, handle)

    # in 3D: the frame on the table, the long bars along x, the short along y
    Place(front_bar, position=(0, -(OPEN_Y / 2), 0), face="front", up="up")
    Place(back_bar, position=(0, OPEN_Y / 2 + t, 0), face="front", up="up")
    Place(left_bar, position=(-(OPEN_X / 2) - t, 0, 0), face="right", up="up")
    Place(right_bar, position=(OPEN_X / 2, 0, 0), face="right", up="up")
    # the squeegee in front of it, the blade's 6 mm between handle and strip
    Place(handle, position=(0, -250, 25), face="front", up="up")
    Place(strip, position=(0, -262, 25), face="front", up="up")

    assert front_bar.h_r.cut.bb.left - front_bar.h_l.cut.bb.right == 360 mm, "opening 360 long"
    assert left_bar.h_r.cut.bb.left - left_bar.h_l.cut.bb.right == 260 mm, "opening 260 wide"
    assert front_bar.body.bb.right - front_bar.h_r.cut.bb.right == 15 mm, "long bars run 15 past"
    assert left_bar.body.bb.right - left_bar.h_r.cut.bb.right == 15 mm, "short bars run 15 past"
    assert front_bar.h_l.cut.bb.height + left_bar.h_l.cut.bb.height == 30 mm, "halvings flush"
    assert front_bar.body.bb.height == 30 mm, "bars 30 tall"
    assert handle.body.bb.width == 280 mm and handle.body.bb.height == 90 mm, "handle 280 x 90"
    assert handle.grip.s.center.y - handle.body.bb.bottom == 55 mm, "hand slot 55 up"
    assert handle.holes.b[1].center.x - handle.holes.b[0].center.x == 70 mm, "bolts 70 apart"
    assert handle.holes.b[0].center.y - handle.body.bb.bottom == 15 mm, "bolts 15 up"
    assert distance(legend, front_bar.h_l) >= 5 mm, "legend clear of the halvings"
}
