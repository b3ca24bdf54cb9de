# Request (crafts): a two-layer bead design board for laying out necklaces, 3 mm ply, 330 x 250
# mm with 12 mm corners. The top layer has two U-shaped channels 10 mm wide for the beads: bead
# lines (the channels' middles) of radius 90 and 110 mm about a centre 20 mm above the board's
# middle, each with straight legs running 80 mm up from the arc's ends. Outside the outer channel
# a cm scale is engraved, measured along the outer bead line from the bottom centre up both
# sides: a 5 mm tick every 10 mm to 25 cm, 9 mm ticks with their number every 5 cm, "0" at the
# bottom. Inside the U, four 70 x 35 mm compartments (8 mm corners) for loose beads, two rows
# of two, and "NECKLACE  cm" engraved above them. The bottom layer is plain and closes it all.

thickness 3 mm

board_w = 330 mm
board_h = 250 mm
cy0 = 20 mm               # the channels' centre, above the board's middle
r_in = 90 mm
r_out = 110 mm
chan_w = 10 mm
leg = 80 mm
arc_half = pi * r_out / 2                     # bead line from the bottom centre to a leg
tick_r = r_out + chan_w / 2 + 1 mm            # ticks start 1 mm outside the outer channel

# the point at bead-line length s from the bottom centre, on side +1 (right) or -1 (left),
# moved out to radius r (on a leg: to x = r)
def tick_pt(s, side, r) = ((side * r * sin(s / r_out * 1 rad), cy0 - r * cos(s / r_out * 1 rad))
                           if s <= arc_half else (side * r, cy0 + s - arc_half))

def channel(r) -> hole {
    arc = ArcSlot(center=(0, cy0), radius=r, start_angle=180 deg, end_angle=360 deg, width=chan_w)
    left = Slot(start=(-r, cy0), end=(-r, cy0 + leg), width=chan_w)
    right = Slot(start=(r, cy0), end=(r, cy0 + leg), width=chan_w)
}

assembly bead_board {
    solid bottom {
        body = RoundedRectangle(center=(0, 0), width=board_w, height=board_h, corner_radius=12 mm)
    }

    solid top {
        body = RoundedRectangle(center=(0, 0), width=board_w, height=board_h, corner_radius=12 mm)
        inner = channel(r=r_in)
        outer = channel(r=r_out)
        hole trays {
            for x in [-38, 38] {
                for y in [15, 60] {
                    t = RoundedRectangle(center=(x * 1 mm, y * 1 mm), width=70 mm, height=35 mm,
                                         corner_radius=8 mm)
                }
            }
        }
        drawing scale {
            zero = Line((0, cy0 - tick_r), (0, cy0 - tick_r - 9 mm))
            zero_label = Text("0", position=(0, cy0 - tick_r - 14 mm), size=4 mm, valign="middle")
            for i in range(1, 26) {
                for side in [-1, 1] {
                    tk = Line(tick_pt(i * 10 mm, side, tick_r),
                              tick_pt(i * 10 mm, side, tick_r + (9 mm if i % 5 == 0 else 5 mm)))
                }
            }
            for n in [5, 10, 15, 20, 25] {
                for side in [-1, 1] {
                    num = Text(str(n), position=tick_pt(n * 10 mm, side, tick_r + 15 mm), size=4 mm,
                               valign="middle")
                }
            }
            title = Text("NECKLACE  cm", position=(0, 92 mm), size=6 mm, valign="middle")
        }
    }

    Above(top, bottom, gap=10)
    Place(bottom, position=(0, 0, 0))
    Place(top, position=(0, 0, 3 mm))

    assert bottom.body.width == 330 mm and bottom.body.height == 250 mm, "board 330 x 250"
    assert top.inner.arc.width == 10 mm, "channels 10 mm wide"
    assert top.inner.arc.radius == 90 mm and top.outer.arc.radius == 110 mm, "bead lines r 90, 110"
    assert top.outer.left.length == 80 mm + 10 mm, "legs 80 mm (slot length is tip to tip)"
    assert sum([len(r) for r in top.trays.t]) == 4, "four compartments"
    assert len(top.scale.tk) == 25 and len(top.scale.tk[0]) == 2, "25 ticks a side"
    assert abs(pi * 110 mm + 2 * 80 mm - (2 * arc_half + 2 * leg)) < 0.01 mm, "outer line length"
}
