# Issue 73 model run, d03: rings of arc slots made by an unnamed pattern in a loop; the
# slots of a ring overlap (one opening meant).
solid grille {
    body = RoundedRectangle(center=(0, 0), width=120, height=120, corner_radius=5)
    for i in range(2) {
        hole ring {
            a = ArcSlot(center=(0, 0), radius=25 + i * 12, start_angle=5, end_angle=90, width=6)
        }
        CircularPattern(ring, 4, body.center)
    }
}
