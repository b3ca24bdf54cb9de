# Request: a sewing pattern weight shaped like a cotton reel, three layers of 3 mm birch ply
# glued round two 40 mm steel washers (1.5 mm each). The reel: a 50 mm wide barrel 60 mm tall
# between two flanges 64 wide and 10 tall (corners R3), 80 mm overall. Top layer: the thread
# engraved as lines across the barrel, slanted 15 degrees from vertical, 4 mm apart, clipped
# to the barrel; "SEW" engraved 5 mm tall in the top flange. Middle layer: a 41 mm pocket for
# the washers in the barrel's middle (walls at least 4 mm). Bottom layer: plain. Laid out in a
# row 6 mm apart to cut (the maker cuts four sets); stacked for a look.

thickness 3 mm

t = 3 mm
barrel_w = 50 mm
barrel_h = 60 mm
flange_w = 64 mm
flange_h = 10 mm
pocket = 41 mm
pitch = 4 mm
slant = 15 deg

def reel(kind="plain") -> solid {
    barrel = Rectangle(center=(0, 0), width=barrel_w, height=barrel_h)
    top_flange = RoundedRectangle(center=(0, barrel_h / 2 + flange_h / 2), width=flange_w,
                                  height=flange_h, corner_radius=3)
    low_flange = RoundedRectangle(center=(0, -barrel_h / 2 - flange_h / 2), width=flange_w,
                                  height=flange_h, corner_radius=3)
    if kind == "pocket" {
        hole washers { c = Circle(center=(0, 0), diameter=pocket) }
    }
    if kind == "top" {
        drawing thread {
            core = Rectangle(center=(0, 0), width=barrel_w, height=barrel_h, construction=true)
            for i in range(27) {
                l = Line((-52 mm + i * pitch - barrel_h / 2 * tan(slant), -barrel_h / 2),
                         (-52 mm + i * pitch + barrel_h / 2 * tan(slant), barrel_h / 2),
                         construction=true)
            }
            lines = Intersect([core] + l)
        }
        drawing word {
            w = Text("SEW", position=(0, barrel_h / 2 + flange_h / 2), size=5, valign="middle")
        }
    }
}

assembly weight {
    bottom = reel()
    middle = reel(kind="pocket")
    top = reel(kind="top")

    RightOf(middle, bottom, gap=6)
    AlignTop(middle, bottom)
    RightOf(top, middle, gap=6)
    AlignTop(top, bottom)

    Place(bottom, position=(0, 0, 0), face="up")
    Place(middle, position=(0, 0, t), face="up")
    Place(top, position=(0, 0, 2 * t), face="up")

    # the request's numbers
    assert top.bb.width == 64 mm and top.bb.height == 80 mm, "reel 64 x 80"
    assert top.barrel.width == 50 mm and top.barrel.height == 60 mm, "barrel 50 x 60"
    assert middle.washers.c.diameter == 41 mm, "41 mm pocket"
    assert (barrel_w - pocket) / 2 >= 4 mm, "walls at least 4 mm"
    assert top.thread.l[1].start.x - top.thread.l[0].start.x == 4 mm, "lines 4 mm apart"
    assert top.thread.lines.bb.left >= top.barrel.bb.left and top.thread.lines.bb.right <= top.barrel.bb.right and
        top.thread.lines.bb.top <= top.barrel.bb.top and top.thread.lines.bb.bottom >= top.barrel.bb.bottom,
        "thread clipped to the barrel"
    assert top.word.w.size == 5 mm, "SEW 5 mm"
    assert top.word.bb.left >= top.top_flange.bb.left + 3 mm and top.word.bb.top <= top.top_flange.bb.top - 1 mm and
        top.word.bb.bottom >= top.top_flange.bb.bottom + 1 mm, "SEW inside the top flange"
    assert 2 * 1.5 mm <= t, "two washers fit the pocket's depth"
}
