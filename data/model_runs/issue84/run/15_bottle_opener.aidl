# A keychain bottle opener: 70 x 24 mm body with round ends (slot shape), a
# cap-lifting opening near one end (an 18 mm wide, 10 mm tall rounded window
# whose top edge is the lip), and a 5 mm key-ring hole at the other end.
solid opener {
    body = Slot(center=(0, 0), length=70, width=24)
    hole mouth { w = RoundedRectangle(center=(-16, -1), width=18, height=10, corner_radius=3) }
    hole ring { c = Circle(center=(27, 0), diameter=5) }
}
