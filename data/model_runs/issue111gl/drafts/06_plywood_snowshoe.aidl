# Request: plywood snowshoes for winter camping (this is one; cut everything twice). 9 mm
# marine ply. The deck: a tapered teardrop 580 mm long and 240 mm wide (a 240 mm round front
# tapering to an 80 mm round tail); a 100 x 70 mm toe opening (15 mm corners) centred 130 mm
# up from the middle for the boot's toe to drop through; behind it, the pivot: two upright
# cheeks 80 mm long and 45 mm tall above the deck (12 mm round top corners), their mid-planes
# 65.5 mm either side of the centre line and centred 90 mm up, each glued into the deck by two
# 15 mm tabs through mortises (0.2 mm clearance), each with a 10.3 mm hole 25 mm above the
# deck for the 10 mm aluminium pivot rod. Two pairs of 30 x 6 mm slots for the binding's
# 25 mm straps, 64 mm either side of the centre line, 30 mm up and 40 mm down; three 16 mm
# snow-shedding holes down the tail 30 mm apart from 200 mm down; "TRAIL 7" engraved filled
# (sans Bold, 16 mm) on the front.

import "std/joints.aidl"

units mm
ply = 9 mm
thickness ply

shoe_len = 580 mm
shoe_w = 240 mm
rod_y = 90 mm
cheek_x = 65.5 mm
cheek_len = 80 mm
cheek_h = 45 mm
tab_w = 15 mm
fit = 0.2 mm

def cheek() -> solid {
    body = RoundedRectangle(bottom_left=(-cheek_len / 2, -ply), width=cheek_len, height=cheek_h + ply,
                            corner_radii=[12, 12, 0, 0])
    Fixed(body)
    feet = tab_and_slot(part="tab", length=cheek_len, thickness=ply, tabs=2, tab=tab_w, screw=0,
                        rotation=180 deg, cx=0, cy=-ply)
    hole rod { c = Circle(center=(0, 25), diameter=10.3) }
}

assembly snowshoe {
    solid deck {
        outline = Hull(Circle(center=(0, 170), radius=120), Circle(center=(0, -250), radius=40))
        hole toe { r = RoundedRectangle(center=(0, 130), width=100, height=70, corner_radius=15) }
        seat_r = tab_and_slot(part="slot", length=cheek_len, thickness=ply, tabs=2, tab=tab_w,
                              screw=0, clearance=fit, rotation=90 deg, cx=cheek_x, cy=rod_y)
        seat_l = tab_and_slot(part="slot", length=cheek_len, thickness=ply, tabs=2, tab=tab_w,
                              screw=0, clearance=fit, rotation=90 deg, cx=-cheek_x, cy=rod_y)
        hole straps {
            for p in [(-64, 30), (64, 30), (-64, -40), (64, -40)] {
                s = Slot(center=p, length=30, width=6, rotation=90 deg)
            }
        }
        hole shed { c = Circle(center=(0, -200), diameter=16) }
        shed_row = LinearPattern(shed, 3, (0, -30))
        drawing name {
            word = Text("TRAIL 7", position=(0, 225), size=16, font="sans:Bold", fill=true,
                        valign="middle")
        }

        assert outline.bb.height == 580 mm and outline.bb.width == 240 mm, "580 x 240 deck"
        assert toe.r.width == 100 mm and toe.r.height == 70 mm, "100 x 70 toe opening"
        assert toe.r.center.y == 130 mm, "toe opening 130 mm up"
        assert distance(toe, seat_r) >= 8 mm and distance(toe, seat_l) >= 8 mm, "ply left between toe and mortises"
        assert distance(straps, outline) >= 10 mm, "strap slots well inside the edge"
        assert straps.s[1].center.x - straps.s[0].center.x == 128 mm, "straps 64 mm either side"
        assert len(shed_row) == 3 and shed_row[0].c.center.y - shed_row[1].c.center.y == 30 mm, "three holes 30 mm apart"
        assert distance(shed_row[2], outline) >= 10 mm, "the last hole inside the tail"
        assert distance(name, toe) >= 10 mm and distance(name, outline) >= 10 mm, "the name on the front"
    }
    cheek_l = cheek()
    cheek_r = cheek()

    # flat: the cheeks beside the deck
    RightOf(cheek_l, deck, gap=10)
    AlignTop(cheek_l, deck)
    Below(cheek_r, cheek_l, gap=10)
    AlignLeft(cheek_r, cheek_l)

    # assembled: the deck flat, the cheeks standing in their mortises, faces outwards
    Place(deck, position=(0, 0, 0))
    Place(cheek_r, position=(cheek_x - ply / 2, rod_y, ply), face="right", up="up")
    Place(cheek_l, position=(-cheek_x + ply / 2, rod_y, ply), face="left", up="up")

    assert cheek_r.rod.c.center.y == 25 mm, "rod 25 mm above the deck"
    assert cheek_r.body.bb.top == 45 mm and cheek_r.body.bb.width == 80 mm, "cheeks 80 long, 45 tall"
    assert deck.seat_r.slot[0].bb.width == ply + fit and deck.seat_r.slot[0].bb.height == tab_w + fit, "mortises fit the tabs"
}
