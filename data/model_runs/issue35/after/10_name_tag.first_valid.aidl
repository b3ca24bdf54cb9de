# name tag 80 x 30, rounded corners, key-ring hole, "ALEX" engraved
solid tag {
    body = RoundedRectangle(center=(0, 0), width=80, height=30, corner_radius=5)
    Fixed(body)
    hole ring { c = Circle(center=(-32, 0), diameter=6) }
    AlignCenterY(ring, body)
    HorizontalDistance(body.left.midpoint, ring.c.center, 7)
    drawing name {
        t = Text("ALEX", (8, 0), size=12, valign="middle")
    }
    AlignCenterY(name, body)
}
