# Guitar pick with a keyring eye: the classic 351 shape, 27 mm wide and 31 mm tall:
# the hull of two 10 mm-radius shoulder circles (centers 3.5 mm either side of the axis)
# and a 2.5 mm-radius tip circle 31 mm below the shoulders' top; a 3 mm hole 5 mm
# below the top edge.

param shoulder_r = 10 mm, min = 8 mm, max = 12 mm

solid pick {
    outline = Hull(Circle(center=(-3.5, 0), radius=shoulder_r),
                   Circle(center=(3.5, 0), radius=shoulder_r),
                   Circle(center=(0, -18.5), radius=2.5))
    hole eye {
        c = Circle(center=(0, 5), diameter=3)
    }
    eye.c.top.y == outline.bb.top - 5 mm
    AlignCenterX(eye, outline)
}
assert pick.outline.bb.width == 27 mm, "27 mm wide"
assert pick.outline.bb.height == 31 mm, "31 mm tall"
assert pick.eye.c.diameter == 3 mm, "3 mm eye"
