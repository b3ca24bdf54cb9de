# Router template for a butt-hinge mortise: a 160 x 100 mm plate of 6 mm MDF.
# The hinge leaf is 76 x 35 mm; the router runs a 16 mm guide bushing with a
# 12 mm bit, so the opening is 2 mm larger on each side: 80 mm wide and 37 mm
# deep (35 + 2, it is open at the top edge, the door's edge), its two inner
# corners rounded 8 mm (the bushing's radius), centered left to right. Two 5 mm
# clamping/screw holes 20 mm above the bottom edge, 25 mm in from each side,
# and an engraved 12 mm center mark below the opening.

units mm
thickness 6 mm

param leaf_w = 76 mm, min = 40 mm, max = 120 mm
param leaf_d = 35 mm, min = 20 mm, max = 60 mm
param bushing = 16 mm, min = 10 mm, max = 30 mm
param bit = 12 mm, min = 6 mm, max = 16 mm

off = (bushing - bit) / 2

solid template {
    body = Rectangle(center=(0, 0), width=160, height=100)

    hole mortise {
        # 5 mm taller than needed so it runs out past the top edge
        opening = RoundedRectangle(center=(0, 30), width=leaf_w + 2 * off,
                                   height=leaf_d + off + 5, corner_radii=[0, 0, bushing / 2, bushing / 2])
    }
    AlignCenterX(mortise, body)
    mortise.opening.bb.top == body.bb.top + 5

    hole clamp {
        c = Circle(center=(-55, -30), diameter=5)
    }
    At(clamp.c.center, body.bottom_left, dx=25, dy=20)
    axis = Line(body.top.midpoint, body.bottom.midpoint, construction=true)
    clamp2 = Mirrored(clamp, about=axis)

    drawing mark {
        l = Line(start=(0, -5), end=(0, -17))
    }
    Vertical(mark.l)
    Length(mark.l, 12)
    AlignCenterX(mark, body)
    Below(mark, mortise, gap=3)
}
