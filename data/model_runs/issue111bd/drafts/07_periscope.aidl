# Request (science): a classroom periscope from 3 mm poplar ply, glued. A square tube 300 mm
# long, 56 x 56 mm outside (50 x 50 inside): two side panels with 15 mm fingers along their
# long edges into the front and back panels' slots, short ends flat, closed by two 56 x 56
# end caps glued on. A 40 x 40 mm window in the front panel at the top and one in the back
# panel at the bottom, each centred 28 mm from its panel's end, in line with a mirror. The
# two mirrors (cut from 2 mm mirror acrylic, 55 x 64 mm) lie at 45 degrees, parallel, their
# edges held in 2.2 mm x 66 mm slots through both side panels, centred 28 mm from the ends.
# "PERISCOPE" engraved filled (12 mm bold) along the front panel's middle, "LOOK" (8 mm
# strokes) on the back panel beside its window.

import "std/joints.aidl"

thickness 3 mm

t = 3 mm
L = 300 mm
outer = 56 mm
inner = outer - 2 * t
win = 40 mm
mirror_at = 28 mm       # mirror and window centres from the tube's ends
slot_len = 66 mm
slot_w = 2.2 mm
mirror_w = 55 mm
mirror_l = 64 mm
s2 = sqrt(2) / 2

def side() -> solid {
    wall = finger_panel(width=L, height=outer, thickness=t, finger=15 mm, bottom="fingers",
                        top="fingers", left="flat", right="flat", cx=L / 2, cy=0 mm)
    # the mirrors run from the front (-y) at the top end (+x) back and down, parallel
    hole top_mirror { s = Slot(center=(L - mirror_at, 0), length=slot_len, width=slot_w, rotation=135 deg) }
    hole bottom_mirror { s = Slot(center=(mirror_at, 0), length=slot_len, width=slot_w, rotation=135 deg) }
}

def face(window_x=28 mm) -> solid {
    wall = finger_panel(width=L, height=outer, thickness=t, finger=15 mm, bottom="slots",
                        top="slots", left="flat", right="flat", cx=L / 2, cy=0 mm)
    hole window { r = Rectangle(center=(window_x, 0), width=win, height=win) }
}

def mirror() -> solid {
    thickness 2 mm
    glass = Rectangle(center=(0, 0), width=mirror_w, height=mirror_l)
}

def cap() -> solid {
    plate = Rectangle(center=(0, 0), width=outer, height=outer)
}

assembly periscope {
    left_side = side()
    right_side = side()
    front = face(window_x=L - mirror_at)
    back = face(window_x=mirror_at)
    top_cap = cap()
    bottom_cap = cap()
    top_glass = mirror()
    bottom_glass = mirror()
    drawing front_words {
        w = Text("PERISCOPE", position=(L / 2, 0), size=12, font="sans:Bold", valign="middle", fill=true)
    }
    drawing back_words {
        w = Text("LOOK", position=(mirror_at + win / 2 + 20 mm, 0), size=8, valign="middle")
    }
    CutInto(front_words, front)
    CutInto(back_words, back)

    # on the sheet
    Fixed(left_side)
    Above(right_side, left_side, gap=8)
    AlignLeft(right_side, left_side)
    Above(front, right_side, gap=8)
    AlignLeft(front, right_side)
    Above(back, front, gap=8)
    AlignLeft(back, front)
    RightOf(top_cap, left_side, gap=8)
    AlignBottom(top_cap, left_side)
    Above(bottom_cap, top_cap, gap=8)
    AlignLeft(bottom_cap, top_cap)
    RightOf(top_glass, top_cap, gap=8)
    AlignBottom(top_glass, top_cap)
    RightOf(bottom_glass, top_glass, gap=8)
    AlignBottom(bottom_glass, top_glass)
    AlignCenterY(front_words, front)
    AlignCenterX(front_words, front)
    AlignCenterY(back_words, back)
    back_words.w.position.x == back.window.r.center.x + win / 2 + 20 mm

    # assembled: the tube along z, x across, y from front (-) to back (+)
    Place(left_side, rotation=(0, -90 deg, 0), position=(-inner / 2, 0, 0))
    Place(right_side, rotation=(0, -90 deg, 0), position=(outer / 2, 0, 0))
    Place(front, rotation=(90 deg, -90 deg, 0), position=(0, -inner / 2, 0))
    Place(back, rotation=(-90 deg, -90 deg, 0), position=(0, inner / 2, 0))
    Place(bottom_cap, position=(0, 0, -t))
    Place(top_cap, position=(0, 0, L))
    Place(top_glass, rotation=(135 deg, 0, 0), position=(0, s2, L - mirror_at + s2))
    Place(bottom_glass, rotation=(135 deg, 0, 0), position=(0, s2, mirror_at + s2))

    # the request's numbers
    assert left_side.wall.outline.width == 300 mm and left_side.wall.outline.height == 56 mm, "tube 300 long, 56 outside"
    assert inner == 50 mm, "50 inside"
    assert front.window.r.width == 40 mm, "40 mm windows"
    assert front.wall.outline.bb.right - front.window.r.center.x == 28 mm, "front window 28 from the top end"
    assert back.window.r.center.x - back.wall.outline.bb.left == 28 mm, "back window 28 from the bottom end"
    assert left_side.top_mirror.s.length == 66 mm and left_side.top_mirror.s.width == 2.2 mm, "mirror slots 2.2 x 66"
    assert top_glass.glass.width == 55 mm and top_glass.glass.height == 64 mm, "mirrors 55 x 64"
    assert mirror_l < slot_len and mirror_w <= inner + 2 * t - 1 mm, "mirrors fit their slots"
}
