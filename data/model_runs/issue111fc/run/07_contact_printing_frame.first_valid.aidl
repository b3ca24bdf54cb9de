# Request: a contact printing frame for A5 cyanotypes, 3 mm ply, glued layers.
# Outside 200 x 260 mm with 6 mm corners. A front frame with a 140 x 200 mm window
# (3 mm corners) and "SUN PRINT" (single-stroke, 8 mm) engraved centred in the top
# margin, "CYANOTYPE A5" (5 mm) in the bottom one. Under it two rebate frames with
# a 162 x 222 mm opening for 160 x 220 mm picture glass, the negative, the paper and
# felt. A split back (so one part can be lifted to check the print): two boards
# 161 mm wide, 146.5 and 73.5 mm tall (a 2:1 split with 0.5 mm between them and to
# the rebate), each with a 20 mm finger hole at its middle. Four turn buttons
# (30 x 12 mm, round ends, 3.4 mm pivot hole 6 mm from one end) screwed (M3 wood
# screws into 2.5 mm pilot holes) to the back of the rebate frames, two each side
# at 60 mm above and 74 mm below the middle, pivots 9.5 mm in from the outer edge.
# Four 4 mm dowel holes 9.5 mm in from both edges at the corners of all three frames.

units mm
thickness 3 mm

W = 200 mm
H = 260 mm
GAP = 0.5 mm
OPEN_W = 162 mm
OPEN_H = 222 mm
TOP_H = 146.5 mm          # the back boards' heights (2:1)
LOW_H = 73.5 mm
PIVOT_X = W / 2 - 9.5 mm

def frame_layer(win_w=162 mm, win_h=222 mm, win_r=0 mm, pilots=true) -> solid {
    body = RoundedRectangle(center=(0, 0), width=W, height=H, corner_radius=6)
    hole window { w = RoundedRectangle(center=(0, 0), width=win_w, height=win_h, corner_radius=win_r) }
    hole dowel { c = Circle(center=(-W / 2 + 9.5 mm, -H / 2 + 9.5 mm), diameter=4) }
    dowels = CornerPattern(dowel, body, inset=9.5 mm)
    if pilots {
        hole pilot { c = Circle(center=(-PIVOT_X, 60), diameter=2.5) }
        p2 = Translated(pilot, (0, -134))
        p3 = Mirrored(pilot, Line((0, -10), (0, 10), construction=true))
        p4 = Mirrored(p2, Line((0, -10), (0, 10), construction=true))
    }
}

def turn_button(px=0 mm, py=0 mm, a=0 deg) -> solid {
    arm = Slot(start=(px, py), length=30 mm - 12 mm, angle=a, width=12)
    hole pivot { c = Circle(center=(px, py), diameter=3.4) }
}

assembly contact_frame {
    front = frame_layer(win_w=140 mm, win_h=200 mm, win_r=3 mm, pilots=false)
    drawing front_words {
        title = Text("SUN PRINT", position=(0, 115), size=8, valign="middle")
        note = Text("CYANOTYPE A5", position=(0, -115), size=5, valign="middle")
    }
    CutInto(front_words, front)
    Rigid(front_words, front)

    rebate_a = frame_layer()
    rebate_b = frame_layer()

    solid back_top {
        board = Rectangle(bottom_left=(-(OPEN_W - 1 mm) / 2, -OPEN_H / 2 + GAP + LOW_H + GAP),
                          width=OPEN_W - 1 mm, height=TOP_H)
        hole lift { c = Circle(center=(0, 0), diameter=20) }
        CenterInside(lift, board)
    }
    solid back_bottom {
        board = Rectangle(bottom_left=(-(OPEN_W - 1 mm) / 2, -OPEN_H / 2 + GAP),
                          width=OPEN_W - 1 mm, height=LOW_H)
        hole lift { c = Circle(center=(0, 0), diameter=20) }
        CenterInside(lift, board)
    }

    # pivots: 6 mm from the button's end, so the arm runs 30 - 12 = 18 mm centre to centre;
    # they point inward over the back boards
    b1 = turn_button(px=-PIVOT_X, py=60 mm, a=0 deg)
    b2 = turn_button(px=-PIVOT_X, py=-74 mm, a=0 deg)
    b3 = turn_button(px=PIVOT_X, py=60 mm, a=180 deg)
    b4 = turn_button(px=PIVOT_X, py=-74 mm, a=180 deg)

    # flat layout: frames in a row, back boards and buttons in a row below
    RightOf(rebate_a, front, gap=8)
    AlignBottom(rebate_a, front)
    RightOf(rebate_b, rebate_a, gap=8)
    AlignBottom(rebate_b, front)
    Below(back_top, front, gap=8)
    AlignLeft(back_top, front)
    RightOf(back_bottom, back_top, gap=8)
    AlignTop(back_bottom, back_top)
    RightOf(b1, back_bottom, gap=8)
    AlignTop(b1, back_top)
    Below(b2, b1, gap=5)
    AlignLeft(b2, b1)
    Below(b3, b2, gap=5)
    AlignLeft(b3, b1)
    Below(b4, b3, gap=5)
    AlignLeft(b4, b1)

    # 3D: lying face up (the front toward the sun), buttons underneath
    Place(front, position=(0, 0, 6), face="up")
    Place(rebate_a, position=(0, 0, 3), face="up")
    Place(rebate_b, position=(0, 0, 0), face="up")
    Place(back_top, position=(0, 0, 0), face="up")
    Place(back_bottom, position=(0, 0, 0), face="up")
    Place(b1, position=(0, 0, -3), face="up")
    Place(b2, position=(0, 0, -3), face="up")
    Place(b3, position=(0, 0, -3), face="up")
    Place(b4, position=(0, 0, -3), face="up")

    assert front.body.width == 200 mm and front.body.height == 260 mm, "200 x 260 outside"
    assert front.window.w.width == 140 mm and front.window.w.height == 200 mm, "window 140 x 200"
    assert rebate_a.window.w.width == 160 mm + 2 mm and rebate_a.window.w.height == 220 mm + 2 mm, "glass + 1 mm a side"
    assert back_top.board.width == 161 mm, "back boards 161 wide"
    assert back_top.board.height == 146.5 mm and back_bottom.board.height == 73.5 mm, "2:1 split"
    assert len(rebate_a.dowels) == 4, "four dowels"
    assert b1.arm.length + 12 mm == 30 mm and b1.arm.width == 12 mm, "buttons 30 x 12"
    assert b3.pivot.c.center.x - b1.pivot.c.center.x == 200 mm - 2 * 9.5 mm, "pivots 9.5 in"
    assert b1.pivot.c.center.y - b2.pivot.c.center.y == 60 mm + 74 mm, "buttons 60 above, 74 below"
    assert b1.arm.end.x - b1.pivot.c.center.x + 6 mm > (200 mm - 162 mm) / 2 - 9.5 mm, "button reaches over the back"
}
