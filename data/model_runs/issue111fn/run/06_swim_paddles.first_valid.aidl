# Request: a pair of swim-training hand paddles, left and right (mirror images, each with its
# own letter reading the right way), cut from 4 mm HDPE. A smooth hand-shaped outline 232
# long from tip to heel and about 170 across, fuller on the thumb side. 19 drainage holes of
# 8 mm in a diamond of rows 3-4-5-4-3 at 22 mm pitch, the middle row 6 above the centre. A
# finger strap through two 14 x 4 slots 24 apart (centres), 95 up; a wrist strap through two
# upright 16 x 4 slots 100 apart, 75 below the centre. "R" or "L" engraved filled, 14 tall,
# between the wrist slots, and the size "M", 6 tall, under it.

thickness 4 mm

PTS = [(0, 120), (40, 113), (68, 90), (80, 45), (76, -10), (62, -65), (36, -103), (0, -112),
       (-38, -103), (-68, -65), (-86, -5), (-86, 45), (-72, 90), (-42, 113)]
ROWS = [3, 4, 5, 4, 3]
PITCH = 22 mm

def paddle(side=1, letter="R") -> solid {
    outline = Spline([(side * p[0], p[1]) for p in PTS], closed=true)
    hole drain {
        for r in range(5) {
            for c in range(ROWS[r]) {
                h = Circle(center=((c - (ROWS[r] - 1) / 2) * PITCH, 50 - r * PITCH), diameter=8)
            }
        }
    }
    hole finger {
        for s in [-1, 1] {
            f = Slot(center=(s * 12, 95), length=14, width=4)
        }
    }
    hole wrist {
        for s in [-1, 1] {
            w = Slot(center=(s * 50, -75), length=16, width=4, rotation=90 deg)
        }
    }
    drawing marks {
        l = Text(letter, position=(0, -75), size=14, font="sans:Bold", valign="middle",
                 fill=true)
        m = Text("M", position=(0, -95), size=6, font="sans:Bold", valign="middle", fill=true)
    }
}

assembly pair {
    left = paddle(side=-1, letter="L")
    right = paddle(side=1, letter="R")
    RightOf(right, left, gap=10)
    AlignBottom(right, left)

    Place(left, position=(-100, 0, 0), face="up")
    Place(right, position=(100, 0, 0), face="up")

    assert right.outline.points[0].y - right.outline.points[7].y == 232 mm, "232 tip to heel"
    assert right.outline.bb.width >= 165 mm and right.outline.bb.width <= 175 mm, "about 170"
    assert sum([len(row) for row in right.drain.h]) == 19, "19 drainage holes"
    assert right.finger.f[1].center.x - right.finger.f[0].center.x == 24 mm, "finger slots 24"
    assert right.wrist.w[1].center.x - right.wrist.w[0].center.x == 100 mm, "wrist slots 100"
    assert distance(right.marks, right.wrist) >= 3 mm, "letter clear of the wrist slots"
}
