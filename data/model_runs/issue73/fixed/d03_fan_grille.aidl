# 120 mm fan grille: 120 x 120 mm plate, 4.5 mm holes on a 105 mm square, concentric ring slots.
solid grille {
    body = RoundedRectangle(center=(0, 0), width=120, height=120, corner_radius=5)
    hole screw { c = Circle(center=(0, 0), diameter=4.5) }
    CornerPattern(screw, body, inset=7.5)
    for i in range(4) {
        hole ring {
            a = ArcSlot(center=(0, 0), radius=15 + i * 12, start_angle=10, end_angle=70, width=6)
        }
        rings = CircularPattern(ring, 4, body.center)
    }
    hole hub_gap { c = Circle(center=(0, 0), diameter=6) }
}
