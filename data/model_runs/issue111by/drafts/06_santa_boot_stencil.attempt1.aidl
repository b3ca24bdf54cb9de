# Request: "A Santa's footprints stencil: on Christmas Eve the kids dust flour through it on
# the hall floor. 0.5 mm polypropylene sheet, 400 x 360 mm, corners r10, with two 8 mm
# hanging holes 15 mm in from the top corners. Two boot prints side by side, the left boot
# and its mirror image the right, their centre lines 170 mm apart, each 242 mm long: a sole
# (toe 84 mm wide, ball 76 mm, waist 60 mm) cut in five tread bars by 6 mm bridges, and a
# heel 70 x 60 mm (r22) split by one 6 mm bridge, 10 mm of sheet between sole and heel.
# Above them HO HO HO cut as a stencil in sans bold, 30 mm tall."

units mm
thickness 0.5 mm

sheet_w = 400 mm
sheet_h = 360 mm
bridge = 6 mm
# the sole's tread bars, bottom and top of each (y in the print's own frame)
bars = [[-70, -26 - bridge / 2], [-26 + bridge / 2, 8 - bridge / 2], [8 + bridge / 2, 42 - bridge / 2],
        [42 + bridge / 2, 76 - bridge / 2], [76 + bridge / 2, 120]]

def boot_print() -> hole {
    toe = Circle(center=(5, 70), radius=42, construction=true)
    ball = Circle(center=(0, 20), radius=38, construction=true)
    waist = Circle(center=(3, -30), radius=30, construction=true)
    sole = Hull(toe, ball, waist, construction=true)
    for b in bars {
        tread = Intersect(sole, Rectangle(corner=(-60, b[0]), opposite=(60, b[1]), construction=true))
    }
    heel = RoundedRectangle(center=(2, -100), width=70, height=60, corner_radius=22,
                            construction=true)
    heel_back = Intersect(heel, Rectangle(corner=(-60, -140), opposite=(60, -100 - bridge / 2),
                                          construction=true))
    heel_front = Intersect(heel, Rectangle(corner=(-60, -100 + bridge / 2), opposite=(60, -60),
                                           construction=true))
}

solid stencil {
    sheet = RoundedRectangle(center=(0, 0), width=sheet_w, height=sheet_h, corner_radius=10)
    hole hang_l { c = Circle(center=(-sheet_w / 2 + 15, sheet_h / 2 - 15), diameter=8) }
    hole hang_r { c = Circle(center=(sheet_w / 2 - 15, sheet_h / 2 - 15), diameter=8) }

    left = boot_print()
    left.heel.center.x == -85 mm
    left.heel.center.y == -140 mm
    axis = Line((0, -sheet_h / 2), (0, sheet_h / 2), construction=true)
    right = Mirrored(left, axis)

    hole words {
        t = Text("HO HO HO", position=(0, 130), size=30, font="sans:Bold", valign="middle",
                 stencil=true)
    }

    # the request's numbers
    assert abs(sheet.bb.width - 400 mm) < 0.01 and abs(sheet.bb.height - 360 mm) < 0.01, "sheet"
    assert abs((left.toe.bb.top - left.heel.bb.bottom) - 242 mm) < 0.01, "print 242 long"
    assert abs(left.toe.diameter - 84 mm) < 0.01 and abs(left.ball.diameter - 76 mm) < 0.01 and
        abs(left.waist.diameter - 60 mm) < 0.01, "toe, ball, waist widths"
    assert abs((left.waist.bb.bottom - left.heel.bb.top) - 10 mm) < 0.01, "10 mm arch bridge"
    assert abs((right.heel.center.x - left.heel.center.x) - 170 mm) < 0.01, "170 apart"
    assert len(left.tread) == 5, "five tread bars"
    assert abs(words.t.size - 30 mm) < 0.01, "30 mm letters"
    assert words.bb.bottom > left.toe.bb.top + 10 mm, "words clear above the toes"
    assert words.bb.top < sheet.bb.top - 15 mm, "words clear of the top edge"
}
