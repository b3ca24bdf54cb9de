# Earbud cord winder: an H-shaped plate 60 mm wide and 40 mm tall with 4 mm rounded
# corners: a 20 mm wide notch 12 mm deep centered in the top edge and one in the bottom
# edge (the cord winds round the 16 mm waist between them); a 12 mm long cut slit into
# the plate from the middle of the left edge and one from the right edge, to lock the
# cord's ends.

solid winder {
    body = RoundedRectangle(center=(0, 0), width=60, height=40, corner_radius=4)
    hole top_notch {
        n = Rectangle(center=(0, 14), width=20, height=12)
    }
    hole bottom_notch {
        n = Rectangle(center=(0, -14), width=20, height=12)
    }
    AlignTop(top_notch, body)
    AlignBottom(bottom_notch, body)
    AlignCenterX(top_notch, body)
    AlignCenterX(bottom_notch, body)
    cut slits {
        left = Line((-30, 0), (-18, 0))
        right = Line((30, 0), (18, 0))
    }
    Coincident(slits.left.start, body.left.midpoint)
    Coincident(slits.right.start, body.right.midpoint)
    Horizontal(slits.left)
    Horizontal(slits.right)
    Length(slits.left, 12)
    Length(slits.right, 12)
}
assert winder.body.bb.width == 60 mm and winder.body.bb.height == 40 mm, "60 x 40"
assert winder.bottom_notch.bb.bottom == winder.body.bb.bottom, "bottom notch opens the edge"
assert winder.top_notch.bb.bottom - winder.bottom_notch.bb.top == 16 mm, "16 mm waist"
assert winder.slits.left.length == 12 mm, "12 mm slits"
