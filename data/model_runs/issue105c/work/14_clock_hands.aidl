# Wall clock hand pair: hour hand 70 mm long, minute hand 100 mm long (from the hub
# centre to the tip), both with a 10 mm round hub with a 5 mm (hour) and 3.5 mm
# (minute) centre hole, the blades tapering from 6 mm to 2 mm (hour) and 4 mm to
# 1.5 mm (minute); separate parts, side by side 20 mm apart.
def hand(length=70 mm, hub=10 mm, bore=5 mm, root=6 mm, tip=2 mm) -> solid {
    hubc = Circle(center=(0, 0), diameter=hub)
    blade = Trapezoid(center=(0, length / 2), bottom_width=root, top_width=tip, height=length)
    blade.bb.bottom == hubc.center.y
    AlignCenterX(blade, hubc)
    hole bore_h {
        c = Circle(center=(0, 0), diameter=bore)
    }
    Concentric(bore_h.c, hubc)
}
assembly hands {
    hour = hand(length=70, bore=5, root=6, tip=2)
    minute = hand(length=100, bore=3.5, root=4, tip=1.5)
    LeftOf(hour, minute, gap=20)
    AlignBottom(hour, minute)
}
