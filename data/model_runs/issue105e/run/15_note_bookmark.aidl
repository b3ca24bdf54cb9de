# Bookmark shaped like an eighth note: an oval head (24 x 17 mm ellipse tilted
# 20 degrees), a 5 mm wide stem rising 110 mm from the head's center line at
# its right side (stem's right edge 11 mm right of the head's center), a
# curling flag from the stem's top running down its right side, 46 mm long,
# and a 4 mm tassel hole in the head's center; the whole note drawn at that
# size, then scaled by 1.25 so the bookmark is about 150 mm tall.

param k = 1.25, min = 1, max = 1.5

solid bookmark {
    solid note {
        head = Ellipse(center=(0, 0), rx=12, ry=8.5, rotation=20 deg)
        stem = Rectangle(bottom_left=(6, 0), width=5, height=110)
        At(stem.bottom_right, head.center, dx=11)
        flag = Polygon([(11, 110), (21, 100), (29, 88), (29, 74), (25, 64), (26, 78), (21, 88), (11, 94)])
        Coincident(flag.points[0], stem.top_right)
        hole tassel { c = Circle(center=(0, 0), diameter=4) }
        Concentric(tassel.c, head)
    }
    Scale(note, k)

    assert note.bb.height > 140 mm and note.bb.height < 160 mm, "about 150 mm tall"
    assert note.stem.height == 110 mm * k, "stem scaled"
}
