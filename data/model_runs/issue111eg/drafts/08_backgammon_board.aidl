# Request: a personalised backgammon set as a gift, in 3 mm birch ply. Board 360 x 260 mm,
# corners R6, an engraved border line 8 mm in from the edge. A bar 16 mm wide down the
# middle (two engraved lines) carries "FOR DAD · LOVE, SAM" engraved filled along it
# (sans, 7 mm), reading bottom to top. Each half holds 12 points, 6 on the top edge and 6 on
# the bottom edge of the border, each an isosceles triangle 26 mm at the base and 100 mm
# tall, 4 mm clear of the border's sides and of the bar; the points alternate filled
# (engraved area) and outline, and facing points differ. 30 counters 24 mm across: 15 dark
# (an engraved filled disc 18 mm across) and 15 light (an engraved ring 18 mm across).

units mm
thickness 3 mm

board_w = 360 mm
board_h = 260 mm
inset = 8 mm
bar_w = 16 mm
pt_base = 26 mm
pt_h = 100 mm
pt_clear = 4 mm
counter_d = 24 mm
# the n-th point from the left of a row (0..11): x of its centre
def pt_x(n) = (-(bar_w / 2 + pt_clear + pt_base / 2 + (5 - n) * pt_base) if n < 6
               else bar_w / 2 + pt_clear + pt_base / 2 + (n - 6) * pt_base)

def dark_counter() -> solid {
    disc = Circle(center=(0, 0), diameter=counter_d)
    drawing face { d = Circle(center=(0, 0), diameter=18, fill=true) }
}

def light_counter() -> solid {
    disc = Circle(center=(0, 0), diameter=counter_d)
    drawing face { d = Circle(center=(0, 0), diameter=18) }
}

assembly backgammon {
    solid board {
        body = RoundedRectangle(center=(0, 0), width=board_w, height=board_h, corner_radius=6)
        drawing lines {
            border = Rectangle(center=(0, 0), width=board_w - 2 * inset, height=board_h - 2 * inset)
            bar_l = Line((-bar_w / 2, -(board_h / 2 - inset)), (-bar_w / 2, board_h / 2 - inset))
            bar_r = Line((bar_w / 2, -(board_h / 2 - inset)), (bar_w / 2, board_h / 2 - inset))
        }
        drawing points {
            # FIX after the first valid program (W0513): an outlined point's base ran along
            # the border line, burning it twice; an outlined point is now its two sides only
            # (the border is its base). Filled points stay triangles.
            for n in range(12) {
                top = Triangle(center=(pt_x(n), board_h / 2 - inset - pt_h / 2), base=pt_base,
                               height=pt_h, rotation=180 deg, fill=true,
                               construction=n % 2 == 1)
                bottom = Triangle(center=(pt_x(n), -(board_h / 2 - inset - pt_h / 2)),
                                  base=pt_base, height=pt_h, fill=true,
                                  construction=n % 2 == 0)
                if n % 2 == 1 {
                    top_sides = Polyline([(pt_x(n) - pt_base / 2, board_h / 2 - inset),
                                          (pt_x(n), board_h / 2 - inset - pt_h),
                                          (pt_x(n) + pt_base / 2, board_h / 2 - inset)])
                } else {
                    bottom_sides = Polyline([(pt_x(n) - pt_base / 2, -(board_h / 2 - inset)),
                                             (pt_x(n), -(board_h / 2 - inset - pt_h)),
                                             (pt_x(n) + pt_base / 2, -(board_h / 2 - inset))])
                }
            }
        }
        # a filled point's base lies on the border line: the fill covers that stretch, so the
        # second pass does not show (W0513 accepted)
        AllowOverlap(points, lines)
        drawing message {
            words = Text("FOR DAD · LOVE, SAM", position=(0, 0), size=7, font="sans",
                         valign="middle", rotation=90 deg, fill=true)
        }
    }
    for i in range(15) {
        dark = dark_counter()
        light = light_counter()
        At(dark.disc.center, board.body.bottom_left, dx=counter_d / 2 + i * (counter_d + 2),
           dy=-(counter_d / 2 + 6))
        At(light.disc.center, board.body.bottom_left, dx=counter_d / 2 + i * (counter_d + 2),
           dy=-(counter_d / 2 + 6 + counter_d + 2))
    }

    assert board.body.bb.width == 360 mm and board.body.bb.height == 260 mm, "board 360 x 260"
    assert board.body.bb.right - board.lines.border.bb.right == 8 mm, "border 8 in"
    assert board.lines.bar_r.start.x - board.lines.bar_l.start.x == 16 mm, "bar 16 wide"
    assert len(board.points.top) == 12 and len(board.points.bottom) == 12, "12 points a row"
    assert board.points.top[0].base == 26 mm and board.points.top[0].height == 100 mm, "26 x 100 points"
    assert board.points.top[0].bb.left - board.lines.border.bb.left == 4 mm, "4 mm clear of the border"
    assert board.lines.bar_l.start.x - board.points.top[5].bb.right == 4 mm, "4 mm clear of the bar"
    assert board.points.top[6].bb.left - board.lines.bar_r.start.x == 4 mm, "4 mm clear of the bar"
    assert board.points.top[11].bb.right == board.lines.border.bb.right - 4 mm, "4 mm clear of the border"
    assert board.points.top[0].bb.top == board.lines.border.bb.top, "top points on the border"
    assert board.points.bottom[0].bb.bottom == board.lines.border.bb.bottom, "bottom points on the border"
    assert board.message.bb.width <= bar_w - 4 mm, "message inside the bar"
    assert len(dark) == 15 and len(light) == 15, "15 counters a side"
    assert dark[0].disc.diameter == 24 mm and counter_d <= pt_base, "24 mm counters fit a point"
}
