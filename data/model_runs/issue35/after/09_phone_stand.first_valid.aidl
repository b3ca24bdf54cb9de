# phone stand: two slotted pieces that cross-halve (3 mm material)
thickness 3 mm
param t = 3 mm
assembly stand {
    solid back {
        body = Polygon([(0, 0), (80, 0), (80, 10), (20, 110), (0, 110)])
        hole slot { s = Rectangle(center=(40, 15), width=t, height=30) }
        # slot from the bottom edge, half the crossing height
        AlignBottom(slot, body)
        HorizontalDistance(body.points[0], slot.s.center, 40)
    }
    solid base {
        body = Polygon([(0, 0), (100, 0), (100, 15), (75, 15), (70, 30), (60, 30), (60, 60), (0, 60)])
        hole slot { s = Rectangle(center=(30, 45), width=t, height=30) }
        AlignTop(slot, body)
        HorizontalDistance(body.points[0], slot.s.center, 30)
    }
    LeftOf(back, base, gap=10)
}
