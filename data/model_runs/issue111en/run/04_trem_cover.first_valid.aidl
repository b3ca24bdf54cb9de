# Request: a back cover for the tremolo cavity of my Strat-style guitar, cut from 2.5 mm
# black/white/black pickguard sheet. 84 x 148 mm, R10 corners, long side along the guitar.
# Six countersunk holes for #4 wood screws (3.2 mm holes, 6.5 mm heads): one at each corner
# 8 mm in from both edges, and one in the middle of each long side, 8 mm in. A row of six
# string-change openings, 6 x 14 mm stadiums standing upright, on the bridge's 10.5 mm string
# pitch, centred across the cover, their centres 30 mm below its top edge. Engraved: a border
# line 13 mm in from the edge (R5 corners) and my shop's name "LUTHERIE DUVAL" filled in an
# italic serif, 6 mm tall at most 50 mm wide, its baseline 25 mm above the bottom edge.

thickness 2.5 mm

W = 84 mm
H = 148 mm
INSET = 8 mm
PITCH = 10.5 mm

solid trem_cover {
    body = RoundedRectangle(center=(0, 0), width=W, height=H, corner_radius=10)
    Fixed(body)

    hole screw { c = Circle(center=(-W / 2 + INSET, -H / 2 + INSET), diameter=3.2) }
    corner_screws = CornerPattern(screw, body, inset=INSET)
    hole left_screw { c = Circle(center=(-W / 2 + INSET, 0), diameter=3.2) }
    hole right_screw { c = Circle(center=(W / 2 - INSET, 0), diameter=3.2) }
    Countersink(corner_screws + [left_screw, right_screw], diameter=6.5 mm)

    hole string { s = Slot(center=(-2.5 * PITCH, H / 2 - 30 mm), length=14, width=6,
                           rotation=90 deg) }
    strings = LinearPattern(string, 6, (PITCH, 0))

    drawing marks {
        border = RoundedRectangle(center=(0, 0), width=W - 26 mm, height=H - 26 mm,
                                  corner_radius=5)
        shop = Text("LUTHERIE DUVAL", position=(0, -H / 2 + 25 mm), size=6,
                    font="serif:Italic", max_width=50 mm, fill=true)
    }

    assert body.width == 84 mm and body.height == 148 mm, "84 x 148"
    assert len(corner_screws) == 4, "four corner screws"
    assert corner_screws[2].c.center.x - corner_screws[0].c.center.x == 84 mm - 16 mm
    assert body.bb.top - corner_screws[2].c.center.y == 8 mm, "8 in from the top"
    assert len(strings) == 6, "six string openings"
    assert strings[5].s.center.x - strings[0].s.center.x == 5 * 10.5 mm, "10.5 pitch"
    assert body.bb.top - strings[0].s.center.y == 30 mm, "30 below the top"
    assert marks.shop.position.y - body.bb.bottom == 25 mm
    assert marks.border.width == 84 mm - 26 mm
}
