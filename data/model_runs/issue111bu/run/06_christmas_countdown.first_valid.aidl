# Request (holidays): a "sleeps till Christmas" countdown to hang on the kitchen door, three
# layers of 3 mm birch ply glued together, with number tiles that drop in from the top.
# - The plaque: 200 mm wide, straight sides 180 mm tall, an arched top rising 40 mm more
#   (220 mm at the middle). Two 5 mm ribbon holes at (+-80, 170) through all three layers.
# - Back layer: the plain plaque.
# - Middle layer: the plaque with a pocket for two tiles side by side (1 mm play all round:
#   78 x 54 mm), its bottom 84 mm up, and a 78 mm wide channel from the pocket out through
#   the top edge so the tiles drop in.
# - Front layer: a 72 x 46 mm window centred on the pocket (the tiles overlap it by 2 to 3 mm
#   each side); engraved, bold filled: "ONLY" (14 mm) above the window, "SLEEPS TILL" (16 mm)
#   and "CHRISTMAS" (18 mm) below it; a filled five-point star (r 14 mm) in the arch.
# - Tiles 38 x 52 mm, the digit engraved filled, bold, 34 mm tall: 0, 1, 2 for the tens and
#   0 to 9 for the units (13 tiles). Assembled, showing 14.

thickness 3 mm

W = 200 mm
SIDE_H = 180 mm
RISE = 40 mm
TILE_W = 38 mm
TILE_H = 52 mm
PLAY = 1 mm
POCKET_W = 2 * TILE_W + 2 * PLAY
POCKET_H = TILE_H + 2 * PLAY
POCKET_Y = 84 mm               # the pocket's bottom
WIN_W = 72 mm
WIN_H = 46 mm
POCKET_CY = POCKET_Y + POCKET_H / 2
DIGITS = ["0", "1", "2", "0", "1", "2", "3", "4", "5", "6", "7", "8", "9"]

def plaque() -> solid {
    bottom = Line((-W / 2, 0), (W / 2, 0))
    right = Line((W / 2, 0), (W / 2, SIDE_H))
    arch = Arc(start=(W / 2, SIDE_H), through=(0, SIDE_H + RISE), end=(-W / 2, SIDE_H))
    left = Line((-W / 2, SIDE_H), (-W / 2, 0))
    hole ribbon_l { c = Circle(center=(-80, 170), diameter=5) }
    hole ribbon_r { c = Circle(center=(80, 170), diameter=5) }
}

def tile(digit="0") -> solid {
    body = RoundedRectangle(center=(0, 0), width=TILE_W, height=TILE_H, corner_radius=2)
    drawing face {
        d = Text(digit, position=(0, 0), size=34, font="sans:Bold", valign="middle", fill=true)
    }
}

assembly countdown {
    solid back {
        outline = plaque()
    }
    solid middle {
        outline = plaque()
        hole pocket {
            p = Rectangle(bottom_left=(-POCKET_W / 2, POCKET_Y), width=POCKET_W, height=POCKET_H)
            channel = Rectangle(bottom_left=(-POCKET_W / 2, POCKET_Y + POCKET_H / 2),
                                width=POCKET_W, height=SIDE_H + RISE)
        }
    }
    solid front {
        outline = plaque()
        hole window { w = Rectangle(center=(0, POCKET_CY), width=WIN_W, height=WIN_H) }
        drawing words {
            only = Text("ONLY", position=(0, POCKET_Y + POCKET_H + 14), size=14,
                        font="sans:Bold", valign="middle", fill=true)
            sleeps = Text("SLEEPS TILL", position=(0, 62), size=16, font="sans:Bold",
                          valign="middle", fill=true)
            christmas = Text("CHRISTMAS", position=(0, 34), size=18, font="sans:Bold",
                             valign="middle", fill=true)
            star = Star(center=(0, 190), points=5, outer_radius=14, inner_radius=6, fill=true)
        }
    }
    for i in range(len(DIGITS)) {
        t = tile(digit=DIGITS[i])
        # on the sheet: two rows right of the plaques
        t.bb.left == 3 * W + 40 mm + (i % 7) * (TILE_W + 4 mm)
        t.bb.bottom == (0 if i < 7 else TILE_H + 6 mm)
    }

    # on the sheet: the three layers side by side
    RightOf(middle, back, gap=6)
    AlignBottom(middle, back)
    RightOf(front, middle, gap=6)
    AlignBottom(front, back)

    # assembled: back, middle, front stacked; "1" and "4" in the pocket
    Place(back, position=(0, 0, 0))
    Place(middle, position=(0, 0, 3))
    Place(front, position=(0, 0, 6))
    Place(t[1], position=(-TILE_W / 2 - 0.5 mm, POCKET_CY, 3))
    Place(t[7], position=(TILE_W / 2 + 0.5 mm, POCKET_CY, 3))

    # the request's numbers
    assert len(t) == 13, "13 tiles"
    assert middle.pocket.p.width == 78 mm and middle.pocket.p.height == 54 mm, "pocket 78 x 54"
    assert front.window.w.width == 72 mm and front.window.w.height == 46 mm, "window 72 x 46"
    assert (2 * TILE_W - WIN_W) / 2 >= 2 mm and (TILE_H - WIN_H) / 2 >= 2 mm, "tiles overlap the window 2 mm"
    assert middle.pocket.p.bb.bottom - middle.outline.bottom.start.y == 84 mm, "pocket 84 up"
    assert back.outline.arch.through.y - back.outline.bottom.start.y == 220 mm, "220 tall"
    assert t[1].digit == "1" and t[7].digit == "4", "shows 14"
}
