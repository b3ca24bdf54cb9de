# Garden pot feet: three identical 6 mm plywood feet, each 60 mm wide and 30 mm tall:
# a flat 60 mm bottom, straight 10 mm sides and a domed top arc (through the middle,
# 30 mm above the bottom) the pot rests on; a 12 mm wide x 5 mm deep drainage notch
# centred in the bottom edge; each foot's number (1, 2, 3) engraved 6 mm tall,
# centred, baseline 12 mm above the bottom. Laid out in a row 10 mm apart.
thickness 6 mm

def foot(n=1) -> solid {
    bottom = Line((0, 0), (60, 0))
    right = Line((60, 0), (60, 10))
    dome = Arc(start=(60, 10), through=(30, 30), end=(0, 10))
    left = Line((0, 10), (0, 0))
    hole notch {
        r = Rectangle(center=(30, 2.5), width=12, height=5)
    }
    drawing num {
        t = Text(str(n), (30, 12), size=6)
    }
}

assembly feet {
    f1 = foot(n=1)
    f2 = foot(n=2)
    f3 = foot(n=3)
    RightOf(f2, f1, gap=10)
    RightOf(f3, f2, gap=10)
    AlignBottom(f2, f1)
    AlignBottom(f3, f1)

    assert f1.bb.width == 60 mm, "60 wide"
    assert f1.bb.height == 30 mm, "30 tall"
    assert f1.dome.through.y - f1.bottom.start.y == 30 mm, "dome top 30 up"
    assert f1.notch.r.width == 12 mm and f1.notch.r.height == 5 mm, "12 x 5 notch"
    assert f2.bb.left - f1.bb.right == 10 mm, "10 apart"
}
