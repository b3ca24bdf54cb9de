# Request (parties, a wedding): two chair-back signs, "Mr" and "Mrs", tied on with ribbon.
# 3 mm ply, to be painted white. The words in Noto Serif Bold Italic, 70 mm cap height
# at most and the same on both (the first check showed "Mrs" at 70 mm makes a 245 mm sign:
# the longer word sets the size so that its sign is 220 wide), cut as the material, standing on a 6 mm rail that runs under their feet (overlapping
# them by 1.5 mm) and 15 mm past the letters at each side, ending in round ends 18 mm
# across with a 5 mm ribbon hole in each. Neither sign wider than 220 mm.

thickness 3 mm

param size = 70 mm, min = 50 mm, max = 90 mm
param rail_h = 6 mm, min = 4 mm, max = 8 mm
param overlap = 1.5 mm, min = 1 mm, max = 3 mm
param run_on = 15 mm, min = 10 mm, max = 25 mm
param end_d = 18 mm, min = 14 mm, max = 24 mm
param ribbon_d = 5 mm, min = 3 mm, max = 7 mm

def chair_sign(word="Mr", letters=70 mm) -> solid {
    w = Text(word, position=(0, 0), size=letters, font="serif:Bold Italic",
             max_width=220 mm - 2 * run_on - end_d)
    rail = Rectangle(center=(w.bb.center_x, overlap - rail_h / 2), width=w.bb.width + 2 * run_on,
                     height=rail_h)
    end_l = Circle(center=rail.left.midpoint, diameter=end_d)
    end_r = Circle(center=rail.right.midpoint, diameter=end_d)
    hole ribbon_l { c = Circle(center=(0, 0), diameter=ribbon_d) }
    hole ribbon_r { c = Circle(center=(0, 0), diameter=ribbon_d) }
    Concentric(ribbon_l.c, end_l)
    Concentric(ribbon_r.c, end_r)
}

assembly chair_signs {
    mrs = chair_sign(word="Mrs", letters=size)
    mr = chair_sign(word="Mr", letters=mrs.w.size)
    Below(mrs, mr, gap=8)
    AlignCenterX(mrs, mr)

    # the request's numbers
    assert mrs.w.size <= 70 mm and mr.w.size == mrs.w.size, "at most 70 mm, both the same"
    assert mr.rail.bb.height == 6 mm, "6 mm rail"
    assert mr.rail.bb.top - mr.w.position.y == 1.5 mm, "rail overlaps the feet by 1.5"
    assert mrs.rail.bb.width - mrs.w.bb.width == 2 * 15 mm, "15 mm past the letters"
    assert mr.end_l.diameter == 18 mm and mr.ribbon_l.c.diameter == 5 mm, "ends and holes"
    assert mr.bb.width <= 220 mm and mrs.bb.width <= 220 mm, "at most 220 wide"
}
