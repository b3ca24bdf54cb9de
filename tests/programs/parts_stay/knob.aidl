# Issue 73: an ellipse with a knob (a child solid) whose center is put on the ellipse: the
# ellipse stays at (0, 0) and the knob comes down to (0, 25) (before: the ellipse moved up
# to (0, 7) to meet the knob).
solid mirror {
    body = Ellipse(center=(0, 0), rx=40, ry=25)
    solid knob { c = Circle(center=(0, 32), radius=5) }
    Coincident(knob.c.center, body)
    AlignCenterX(knob, body)
}
