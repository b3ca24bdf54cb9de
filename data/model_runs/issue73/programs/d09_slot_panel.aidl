# 200 x 100 mm panel, row of 8 slots 3 x 30 mm, spaced 20 mm, centred.
solid panel {
    body = Rectangle(center=(0, 0), width=200, height=100)
    hole slot { s = Slot(center=(0, 0), length=30, width=3, rotation=90) }
    slots = LinearPattern(slot, 8, (20, 0))
    HorizontalDistance(slots[0].s.center, body.center, 70)
    AlignCenterY(slot, body)
}
