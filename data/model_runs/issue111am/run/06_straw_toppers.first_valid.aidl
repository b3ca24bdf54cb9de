# Request (parties): five star straw toppers spelling P-A-R-T-Y, 2 mm card-thin birch ply.
# Each is a 5-point star, 70 mm across the tips (outer radius 35, inner 18, tips R1.5), with
# its letter cut through as a stencil (bold, 14 mm) in the middle, and two 8 x 1.6 mm slits
# 12 mm above and below the centre to thread a 6 mm paper straw through. Laid out in a row
# 80 mm apart for one cut.
units mm
thickness 2 mm

letters = ["P", "A", "R", "T", "Y"]

def topper(ch="P") -> solid {
    star = Star(center=(0, 0), points=5, outer_radius=35, inner_radius=18, tip_radius=1.5)
    hole letter {
        t = Text(ch, (0, 0), size=14, font="sans:Bold", valign="middle", stencil=true)
    }
    hole slits {
        up = Slot(center=(0, 12), length=8, width=1.6)
        down = Slot(center=(0, -12), length=8, width=1.6)
    }
    CenterInside(letter, star)
}

assembly toppers {
    for i in range(5) {
        s = topper(ch=letters[i])
    }
    for i in range(1, 5) {
        HorizontalDistance(s[i - 1].star.center, s[i].star.center, 80)
        AlignCenterY(s[i], s[0])
    }
    assert len(s) == 5, "five toppers"
    assert s[0].star.outer_radius == 35 mm and s[0].star.inner_radius == 18 mm, "star size"
    assert s[1].star.center.x - s[0].star.center.x == 80 mm, "80 mm apart"
}
