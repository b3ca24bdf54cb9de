# Request: a tabletop Wardian case (a closed terrarium for ferns and moss). 3 mm birch ply box,
# finger-jointed, 220 x 150 x 180 mm outside, 12 mm fingers, with a lift-off lid. Every wall
# has a window with R6 corners: a 45 mm band at the bottom (hides the soil), 15 mm at the top
# and 20 mm at each side, so front and back windows are 180 x 120 and the side windows
# 110 x 120. "FERNERY" in serif capitals 18 mm high, filled engraving, centred in the front's
# bottom band. The lid has 18 vent holes 8 mm across, 3 rows x 6 on a 30 mm grid, centred.
# Four glazing panes in 2 mm clear acrylic, R3 corners, each 8 mm larger than its window all
# round (196 x 136 front and back, 126 x 136 sides), glued inside the walls.

import "std/joints.aidl"

thickness 3 mm

L = 220 mm
D = 150 mm
H = 180 mm
band = 45 mm
top_rail = 15 mm
side_rail = 20 mm
lap = 8 mm
win_w = L - 2 * side_rail
win_d = D - 2 * side_rail
win_h = H - band - top_rail

def pane(w=100 mm, h=100 mm) -> solid {
    thickness 2 mm
    glass = RoundedRectangle(center=(0, 0), width=w, height=h, corner_radius=3)
}

def window(w=100 mm, h=100 mm) -> hole {
    opening = RoundedRectangle(center=(0, 0), width=w, height=h, corner_radius=6)
}

assembly case {
    box = finger_box(length=L, depth=D, height=H, thickness=3 mm, finger=12 mm, closed=true)

    # windows: front and back upright (top edge +y); the left lies with its top edge at -x,
    # the right with its top edge at +x
    front_win = window(w=win_w, h=win_h)
    AlignCenterX(front_win, box.front)
    front_win.bb.bottom == box.front.bb.bottom + band
    CutInto(front_win, box.front)

    back_win = window(w=win_w, h=win_h)
    AlignCenterX(back_win, box.back)
    back_win.bb.bottom == box.back.bb.bottom + band
    CutInto(back_win, box.back)

    left_win = window(w=win_h, h=win_d)
    AlignCenterY(left_win, box.left)
    left_win.bb.left == box.left.bb.left + top_rail
    CutInto(left_win, box.left)

    right_win = window(w=win_h, h=win_d)
    AlignCenterY(right_win, box.right)
    right_win.bb.right == box.right.bb.right - top_rail
    CutInto(right_win, box.right)

    # the name in the front's bottom band
    drawing name {
        t = Text("FERNERY", position=(0, 0), size=18, font="serif", valign="middle", fill=true)
    }
    AlignCenterX(name, box.front)
    name.t.position.y == box.front.bb.bottom + band / 2
    CutInto(name, box.front)

    # lid vents
    hole vent { c = Circle(center=(0, 0), diameter=8) }
    vents = GridPattern(vent, 3, 6, (30, 30))
    vents[0].c.center.x == box.lid.bb.center_x - 2.5 * 30 mm
    vents[0].c.center.y == box.lid.bb.center_y - 30 mm
    CutInto(vent, box.lid)

    # glazing panes, laid out to the right of the net
    front_pane = pane(w=win_w + 2 * lap, h=win_h + 2 * lap)
    back_pane = pane(w=win_w + 2 * lap, h=win_h + 2 * lap)
    left_pane = pane(w=win_d + 2 * lap, h=win_h + 2 * lap)
    right_pane = pane(w=win_d + 2 * lap, h=win_h + 2 * lap)
    RightOf(front_pane, box, gap=10)
    AlignTop(front_pane, box)
    RightOf(back_pane, front_pane, gap=6)
    AlignTop(back_pane, front_pane)
    Below(left_pane, front_pane, gap=6)
    AlignLeft(left_pane, front_pane)
    RightOf(right_pane, left_pane, gap=6)
    AlignTop(right_pane, left_pane)

    # in 3D the box stands on z = 0 centred on x = y = 0, walls 3 mm thick; each pane against
    # the inside face of its wall, centred on its window (window centre band + win_h / 2 up)
    zc = band + win_h / 2
    Place(front_pane, position=(0, -D / 2 + 5 mm, zc), face="front", up="up")
    Place(back_pane, position=(0, D / 2 - 5 mm, zc), face="back", up="up")
    Place(left_pane, position=(-L / 2 + 5 mm, 0, zc), face="left", up="up")
    Place(right_pane, position=(L / 2 - 5 mm, 0, zc), face="right", up="up")

    # the request's numbers
    assert box.front.bb.width == 220 mm and box.front.bb.height == 180 mm
    assert box.left.bb.height == 150 mm
    assert front_win.opening.width == 180 mm and front_win.opening.height == 120 mm
    assert left_win.opening.width == 120 mm and left_win.opening.height == 110 mm
    assert front_win.bb.bottom - box.front.bb.bottom == 45 mm
    assert box.front.bb.top - front_win.bb.top == 15 mm
    assert front_win.bb.left - box.front.bb.left == 20 mm
    assert left_win.bb.left - box.left.bb.left == 15 mm
    assert box.right.bb.right - right_win.bb.right == 15 mm
    assert len(vents) == 18
    assert vents[0].c.diameter == 8 mm
    assert front_pane.glass.width == 196 mm and front_pane.glass.height == 136 mm
    assert left_pane.glass.width == 126 mm and left_pane.glass.height == 136 mm
    assert name.t.size == 18 mm
    assert distance(name, front_win) >= 5 mm, "name clear of the window"
}
