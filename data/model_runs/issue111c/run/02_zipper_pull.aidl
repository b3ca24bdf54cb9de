# Zipper pull: a 45 x 14 mm stadium tab, a 6 x 3 mm slot for the zipper's ring
# 5 mm from the left end (slot center 7 mm from the left tip), and a 5 mm
# diameter decorative hole 7 mm from the right tip.
thickness 3 mm

solid pull {
    tab = Slot(center=(0, 0), length=45, width=14)
    hole ring {
        s = Slot(center=(-15, 0), length=6, width=3, rotation=90 deg)
    }
    hole deco {
        c = Circle(center=(15, 0), diameter=5)
    }
    ring.s.center.x == tab.bb.left + 7 mm
    AlignCenterY(ring, tab)
    deco.c.center.x == tab.bb.right - 7 mm
    AlignCenterY(deco, tab)
}

assert pull.tab.bb.width == 45 mm, "45 mm long"
assert pull.tab.bb.height == 14 mm, "14 mm wide"
assert pull.ring.bb.height == 6 mm and pull.ring.bb.width == 3 mm, "6 x 3 mm slot across the tab"
assert pull.ring.s.center.x - pull.tab.bb.left == 7 mm, "slot center 7 mm from the left tip"
assert pull.tab.bb.right - pull.deco.c.center.x == 7 mm, "hole 7 mm from the right tip"
assert pull.deco.c.diameter == 5 mm, "5 mm hole"
