# Request (gifts): a wooden bifold card wallet, a present engraved with the recipient's
# initials. 2 mm birch ply, one piece that folds on a living hinge.
# - Two covers 92 x 65 mm each (bank cards are 85.6 x 54), corners R6 on the outline, joined by
#   a living-hinge band in the middle that folds the wallet shut round a 4 mm inside radius,
#   the engraved face outside.
# - On the back cover, two 20 x 2.5 mm slots (round ends, upright) 12 mm in from the cover's
#   outer and inner edges, for an elastic strap that holds the cards inside.
# - On the front cover, "E·R" engraved filled in serif, 18 mm, in the middle, inside an engraved
#   border line 4 mm in from the cover's edges (R3 corners).

import "std/plates.aidl"

thickness 2 mm
t = 2 mm

cover_w = 92 mm
cover_h = 65 mm
r_in = 4 mm
band = pi * (r_in + t / 2)       # the sheet a 180 deg fold takes
left_c = -(band / 2 + cover_w / 2)
right_c = band / 2 + cover_w / 2

assembly gift {
    solid wallet {
        body = RoundedRectangle(center=(0, 0), width=2 * cover_w + band, height=cover_h,
                                corner_radius=6)
        hinge = living_hinge(width=band, height=cover_h, pitch=2 mm, cut=15 mm, bridge=3 mm,
                             cx=0, cy=0)
        hole strap {
            outer = Slot(center=(right_c + cover_w / 2 - 12 mm, 0), length=20, width=2.5,
                         rotation=90 deg)
            inner = Slot(center=(right_c - cover_w / 2 + 12 mm, 0), length=20, width=2.5,
                         rotation=90 deg)
        }
        drawing front {
            border = RoundedRectangle(center=(left_c, 0), width=cover_w - 8, height=cover_h - 8,
                                      corner_radius=3)
            initials = Text("E·R", position=(left_c, 0), size=18, font="serif", fill=true,
                            valign="middle")
        }
    }
    Place(wallet, position=(0, 0, 0))
    # shut: the right (back) cover folds under the front, the engraved face outside
    Bend(wallet, at=0, angle=-180 deg, radius=r_in)

    assert wallet.body.bb.width == 2 * 92 mm + band, "two 92 mm covers and the band"
    assert wallet.body.bb.height == 65 mm, "65 tall"
    assert 92 mm >= 85.6 mm + 4 mm and 65 mm >= 54 mm + 4 mm, "a bank card fits with room"
    assert wallet.strap.outer.length == 20 mm and wallet.strap.outer.width == 2.5 mm, "slots 20 x 2.5"
    assert wallet.body.bb.right - wallet.strap.outer.center.x == 12 mm, "slot 12 in from outer edge"
    assert wallet.strap.inner.center.x - band / 2 == 12 mm, "slot 12 in from inner edge"
    assert wallet.front.border.width == 92 mm - 2 * 4 mm, "border 4 mm in"
    assert distance(wallet.front, wallet.hinge) >= 3 mm, "engraving clear of the hinge"
}
