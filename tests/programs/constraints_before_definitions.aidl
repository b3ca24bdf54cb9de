// Issue 14: constraint statements may name geometry defined below them (they run after the
// body's definitions); a definition may only use names defined above it.
units mm

solid bracket {
    Above(tab, base, gap=-2 mm)      // overlap, so that the bracket is one piece
    AlignCenterX(tab, base)
    Fillet([base.plate.top, base.plate.right], radius=2)
    solid base {
        plate = Rectangle(center=(0, 0), width=60, height=10)
    }
    solid tab {
        ear = Slot(center=(0, 20), length=20, width=10, rotation=90 deg)
    }
}
