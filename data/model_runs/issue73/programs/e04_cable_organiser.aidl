# A cable organiser: a comb strip with five slots for cables.
param n = 5
param pitch = 18 mm
solid comb {
    strip = RoundedRectangle(center=(0, 0), width=n * pitch + 10, height=30, corner_radius=4)
    hole slot {
        s = Slot(start=(0, 15), end=(0, 2), width=6)
        c = Circle(center=(0, 2), diameter=9)
    }
    slots = LinearPattern(slot, n, (pitch, 0))
    HorizontalDistance(strip.bb.left, slot.c.center, 14)
    hole screw { a = Circle(center=(-40, -9), diameter=4) }
    screws = Mirrored(screw, about=Line((0, -20), (0, 20), construction=true))
}
