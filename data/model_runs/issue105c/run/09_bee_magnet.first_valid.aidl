# Bee fridge magnet outline: an ellipse body 50 x 34 mm, a round head 20 mm across
# at the left touching the body, two wings (ellipses 16 x 24 mm) on top, overlapping
# the body, a 12 mm pocket for a round magnet in the body's centre is NOT cut (engraved
# ring only), three engraved stripes across the body.
solid bee {
    body = Ellipse(center=(0, 0), rx=25, ry=17)
    head = Circle(center=(-33, 0), diameter=20)
    wing_l = Ellipse(center=(-7, 18), rx=8, ry=12, rotation=20)
    wing_r = Ellipse(center=(7, 18), rx=8, ry=12, rotation=-20)
    stinger = Triangle(center=(28, 0), base=8, height=8, rotation=-90)
    AlignCenterY(head, body)
    head.bb.right == body.bb.left + 3
    AlignCenterY(stinger, body)
    stinger.bb.left == body.bb.right - 2
    drawing stripes {
        for i in range(3) {
            s = Line((-8 + i * 10, -15), (-8 + i * 10, 15))
        }
    }
    CenterInside(stripes, body)
}
