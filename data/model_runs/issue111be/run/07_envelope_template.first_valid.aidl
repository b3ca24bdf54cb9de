# Request (crafts): a tracing template for making C6 envelopes (114 x 162 mm, for A6 cards),
# 3 mm MDF. The envelope's net: a 162 x 114 mm middle panel; 30 mm side flaps tapering from
# 114 mm at the fold to 70 mm; an 80 mm bottom flap tapering from 162 mm to 100 mm; a 65 mm
# top flap with a 20 mm radius round tip. Along each of the four folds a 1.5 mm scoring slot
# in two halves with a 10 mm bridge in the middle, stopping 6 mm short of each corner, to run
# a bone folder through. A 25 mm finger hole 20 mm below the middle; "C6  114 x 162" engraved
# 7 mm high 22 mm above the middle and "for A6 cards" 4 mm high under it; "TOP", "BOTTOM" and
# "GLUE" (on the sides, turned along them) engraved 5 mm on the flaps. Corners rounded 3 mm.

units mm
thickness 3 mm

pw = 162 mm        # middle panel, wide
ph = 114 mm        # middle panel, tall
side_d = 30 mm
side_tip = 70 mm
bot_d = 80 mm
bot_tip = 100 mm
top_d = 65 mm
top_r = 20 mm
score_w = 1.5 mm
stop = 6 mm        # scoring slots stop this short of each corner
bridge = 10 mm

solid envelope_template {
    panel = Rectangle(center=(0, 0), width=pw, height=ph)
    left_flap = Trapezoid(center=(-pw / 2 - side_d / 2, 0), bottom_width=ph, top_width=side_tip,
                          height=side_d, rotation=90 deg)
    right_flap = Trapezoid(center=(pw / 2 + side_d / 2, 0), bottom_width=ph, top_width=side_tip,
                           height=side_d, rotation=-90 deg)
    bottom_flap = Trapezoid(center=(0, -ph / 2 - bot_d / 2), bottom_width=pw, top_width=bot_tip,
                            height=bot_d, rotation=180 deg)
    top_flap = Hull(Point(-pw / 2, ph / 2), Point(pw / 2, ph / 2),
                    Circle(center=(0, ph / 2 + top_d - top_r), radius=top_r))
    Fixed(panel)

    hole scores {
        # the two long folds (top, bottom) and the two short ones (sides), each in two halves
        top_l = Slot(start=(-pw / 2 + stop + score_w / 2, ph / 2), end=(-bridge / 2 - score_w / 2, ph / 2), width=score_w)
        top_r = Slot(start=(bridge / 2 + score_w / 2, ph / 2), end=(pw / 2 - stop - score_w / 2, ph / 2), width=score_w)
        bot_l = Slot(start=(-pw / 2 + stop + score_w / 2, -ph / 2), end=(-bridge / 2 - score_w / 2, -ph / 2), width=score_w)
        bot_r = Slot(start=(bridge / 2 + score_w / 2, -ph / 2), end=(pw / 2 - stop - score_w / 2, -ph / 2), width=score_w)
        left_lo = Slot(start=(-pw / 2, -ph / 2 + stop + score_w / 2), end=(-pw / 2, -bridge / 2 - score_w / 2), width=score_w)
        left_hi = Slot(start=(-pw / 2, bridge / 2 + score_w / 2), end=(-pw / 2, ph / 2 - stop - score_w / 2), width=score_w)
        right_lo = Slot(start=(pw / 2, -ph / 2 + stop + score_w / 2), end=(pw / 2, -bridge / 2 - score_w / 2), width=score_w)
        right_hi = Slot(start=(pw / 2, bridge / 2 + score_w / 2), end=(pw / 2, ph / 2 - stop - score_w / 2), width=score_w)
    }
    hole finger { c = Circle(center=(0, -20), diameter=25) }

    drawing labels {
        size_t = Text("C6  114 x 162", position=(0, 22), size=7, valign="middle")
        use_t = Text("for A6 cards", position=(0, 10), size=4, valign="middle")
        top_t = Text("TOP", position=(0, ph / 2 + 25), size=5, valign="middle")
        bot_t = Text("BOTTOM", position=(0, -ph / 2 - 35), size=5, valign="middle")
        left_t = Text("GLUE", position=(-pw / 2 - side_d / 2, 0), size=5, valign="middle",
                      rotation=90 deg)
        right_t = Text("GLUE", position=(pw / 2 + side_d / 2, 0), size=5, valign="middle",
                       rotation=-90 deg)
    }
    Fillet(3)

    assert panel.width == 162 mm and panel.height == 114 mm, "C6 middle panel"
    assert self.bb.width == 162 mm + 2 * 30 mm, "side flaps 30 mm"
    assert self.bb.height == 114 mm + 80 mm + 65 mm, "flaps 80 and 65 mm"
    assert scores.top_l.start.y - scores.bot_l.start.y == 114 mm, "long folds 114 apart"
    assert scores.right_lo.start.x - scores.left_lo.start.x == 162 mm, "short folds 162 apart"
    assert scores.top_r.start.x - scores.top_l.end.x - score_w == 10 mm, "10 mm bridge"
    assert scores.top_l.start.x - score_w / 2 - panel.bb.left == 6 mm, "stops 6 short"
    assert scores.left_hi.end.y + score_w / 2 + 6 mm == panel.bb.top, "side stops 6 short"
    assert finger.c.diameter == 25 mm and panel.center.y - finger.c.center.y == 20 mm, "finger hole"
}
