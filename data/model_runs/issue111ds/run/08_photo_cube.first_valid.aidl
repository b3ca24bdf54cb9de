# Request (gifts): a photo cube for a first anniversary. 3 mm birch ply, a closed
# finger-jointed cube 100 mm outside, 10 mm fingers. Windows for 80 mm photos glued inside:
# the front and back a 70 x 70 square with R8 corners, the left and right a 70 mm circle,
# all centred. The lid: a heart-shaped window 51 wide (two 27 mm circles at +-12 mm, 7.5 up,
# hulled to a point 24 mm below the middle), "OUR FIRST YEAR" 7 mm bold engraved filled
# above it (baseline 30 mm up) and "2026" 7 mm under it (baseline 38 mm down).

import "std/joints.aidl"

thickness 3 mm

param side = 100 mm, min = 80 mm, max = 150 mm
param t = 3 mm, min = 3 mm, max = 4 mm
param win = 70 mm, min = 50 mm, max = 110 mm

assembly photo_cube {
    cube = finger_box(length=side, depth=side, height=side, thickness=t, finger=10 mm)

    hole front_win {
        w = RoundedRectangle(center=(0, 0), width=win, height=win, corner_radius=8)
    }
    CenterInside(front_win, cube.front)
    CutInto(front_win, cube.front)

    hole back_win {
        w = RoundedRectangle(center=(0, 0), width=win, height=win, corner_radius=8)
    }
    CenterInside(back_win, cube.back)
    CutInto(back_win, cube.back)

    hole left_win { c = Circle(center=(0, 0), diameter=win) }
    CenterInside(left_win, cube.left)
    CutInto(left_win, cube.left)

    hole right_win { c = Circle(center=(0, 0), diameter=win) }
    CenterInside(right_win, cube.right)
    CutInto(right_win, cube.right)

    hole heart {
        a = Hull(Circle(center=(-12, 7.5), radius=13.5), Point(0, -24))
        b = Hull(Circle(center=(12, 7.5), radius=13.5), Point(0, -24))
    }
    drawing words {
        top = Text("OUR FIRST YEAR", position=(0, 30), size=7, font="sans:Bold", fill=true)
        year = Text("2026", position=(0, -38), size=7, font="sans:Bold", fill=true)
    }
    # the heart's point and the words are placed from the lid's middle
    AlignCenterX(heart, cube.lid)
    heart.a.center.y == cube.lid.bb.center_y + (7.5 mm + 13.5 mm - 24 mm) / 2
    AlignCenterX(words, cube.lid)
    words.top.position.y == cube.lid.bb.center_y + 30 mm
    CutInto(heart, cube.lid)
    CutInto(words, cube.lid)

    # the request's numbers
    assert front_win.w.bb.width == 70 mm and left_win.c.diameter == 70 mm, "70 mm windows"
    assert heart.bb.width == 51 mm, "heart 51 wide"
    assert heart.bb.bottom - cube.lid.bb.center_y == -24 mm, "point 24 mm below the middle"
    assert words.year.position.y - cube.lid.bb.center_y == -38 mm, "2026 38 mm down"
    assert words.top.bb.top < cube.lid.bb.top - 6 mm, "words clear of the lid's slots"
    assert words.top.bb.width < 100 mm - 2 * 10 mm, "words clear of the fingers"
    assert win + 2 * 5 mm <= 80 mm, "an 80 mm photo overlaps each window by 5 mm"
}
