# Request (gifts): a book of love coupons for my partner's birthday. Two covers in 3 mm
# cherry ply and five coupon pages in 1.5 mm ply, all 150 x 80 mm with 6 mm rounded
# corners, bound by two book rings through 6 mm holes 10 mm in from the left edge,
# 44 mm apart, centred top to bottom. Front cover: LOVE (14 mm) over COUPONS (9 mm),
# bold serif, filled, centred on each other 15 mm left of the cover's middle, and a
# heart-shaped window (34 mm wide, 30 mm tall) cut through on the right, centred
# 40 mm right of the middle. Back cover: MADE WITH LOVE 2026 engraved 4 mm tall,
# centred. Each coupon: a border engraved from 20 mm in at the left (past the rings)
# to 4 mm in from the other edges, its offer in 6 mm single-stroke capitals centred
# in the border, 4 mm above the middle, and VALID FOREVER 3.5 mm tall 14 mm below the
# middle. Offers: BREAKFAST IN BED, ONE FREE HUG, MOVIE NIGHT, I DO THE DISHES,
# A DAY OUT.
# FIX after the first valid program: the back cover had its ring holes on the left,
# like the front, with its engraving on the top face: bound into the book, its
# engraved face would look inward at the last coupon, not out of the back. Seen from
# outside, the back cover's rings are on the right: its holes now sit 10 mm in from
# the right edge (no message could know which face I meant; my slip).

thickness 3 mm

page_w = 150 mm
page_h = 80 mm
ring_in = 10 mm
ring_gap = 44 mm
offers = ["BREAKFAST IN BED", "ONE FREE HUG", "MOVIE NIGHT", "I DO THE DISHES", "A DAY OUT"]

# border of the coupon's face, from 20 mm in at the left to 4 mm in elsewhere
face_l = -page_w / 2 + 20 mm
face_r = page_w / 2 - 4 mm
face_cx = (face_l + face_r) / 2

def coupon(offer="ONE FREE HUG") -> solid {
    thickness 1.5 mm
    body = RoundedRectangle(center=(0, 0), width=150, height=80, corner_radius=6)
    hole rings {
        top = Circle(center=(-65, 22), diameter=6)
        bottom = Circle(center=(-65, -22), diameter=6)
    }
    drawing face {
        border = RoundedRectangle(corner=(face_l, -36), opposite=(face_r, 36), corner_radius=3)
        words = Text(offer, position=(face_cx, 4), size=6, valign="middle", max_width=110)
        valid = Text("VALID FOREVER", position=(face_cx, -14), size=3.5, valign="middle")
    }
}

assembly book {
    solid front {
        body = RoundedRectangle(center=(0, 0), width=page_w, height=page_h, corner_radius=6 mm)
        hole rings {
            top = Circle(center=(-page_w / 2 + ring_in, ring_gap / 2), diameter=6 mm)
            bottom = Circle(center=(-page_w / 2 + ring_in, -ring_gap / 2), diameter=6 mm)
        }
        hole window {
            lobe_l = Hull(Circle(center=(32, 5), radius=9), Point(40, -16))
            lobe_r = Hull(Circle(center=(48, 5), radius=9), Point(40, -16))
        }
        drawing title {
            love = Text("LOVE", position=(-15, 8), size=14 mm, font="serif:Bold", fill=true,
                        valign="middle")
            coupons = Text("COUPONS", position=(-15, -12), size=9 mm, font="serif:Bold",
                           fill=true, valign="middle")
        }
        Fixed(body)
    }

    solid back {
        body = RoundedRectangle(center=(0, 0), width=page_w, height=page_h, corner_radius=6 mm)
        hole rings {
            top = Circle(center=(page_w / 2 - ring_in, ring_gap / 2), diameter=6 mm)
            bottom = Circle(center=(page_w / 2 - ring_in, -ring_gap / 2), diameter=6 mm)
        }
        drawing note {
            t = Text("MADE WITH LOVE 2026", position=(0, 0), size=4 mm, valign="middle")
        }
    }
    RightOf(back, front, gap=5 mm)
    AlignTop(back, front)

    for i in range(5) {
        c = coupon(offer=offers[i])
    }
    Below(c[0], front, gap=5 mm)
    AlignLeft(c[0], front)
    Below(c[1], front, gap=5 mm)
    AlignLeft(c[1], back)
    Below(c[2], c[0], gap=5 mm)
    AlignLeft(c[2], c[0])
    Below(c[3], c[1], gap=5 mm)
    AlignLeft(c[3], c[1])
    Below(c[4], c[2], gap=5 mm)
    AlignLeft(c[4], c[2])

    assert len(c) == 5, "five coupons"
    assert front.body.bb.width == 150 mm and front.body.bb.height == 80 mm, "150 x 80"
    assert front.rings.top.center.x - front.body.bb.left == 10 mm, "rings 10 mm in"
    assert front.rings.top.center.y - front.rings.bottom.center.y == 44 mm, "rings 44 mm apart"
    assert c[0].rings.top.center.x - c[0].body.bb.left == 10 mm, "coupon rings 10 mm in"
    assert c[0].rings.top.center.y - c[0].rings.bottom.center.y == 44 mm, "coupon rings 44 mm apart"
    assert c[0].rings.top.center.y - c[0].body.bb.center_y == 22 mm, "coupon rings centred"
    assert front.window.bb.width == 34 mm and front.window.bb.height == 30 mm, "34 x 30 heart"
    assert front.window.bb.center_x - front.body.bb.center_x == 40 mm, "heart 40 mm right"
    assert distance(front.title, front.window) >= 5 mm, "title clear of the heart"
    assert front.title.bb.left - front.rings.top.bb.right >= 5 mm, "title clear of the rings"
    assert back.body.bb.right - back.rings.top.center.x == 10 mm, "FIX: back's rings on its right, seen from outside"
    assert c[0].face.border.bb.left - c[0].body.bb.left == 20 mm, "border 20 mm in at the left"
}
