# Request (parties): a pair of wedding chair signs, "Mr" and "Mrs", to hang on the backs of the
# couple's chairs, cut from 3 mm ply. Each word is cut out as the part in a bold serif, 60 mm cap
# height, standing on a rail 8 mm tall that runs under the letters and 15 mm past them each
# side; each end of the rail is an 18 mm round ear with a 5 mm hole for the ribbon. Each sign
# must be no wider than 260 mm to sit on a chair back.

thickness 3 mm

param cap = 60 mm, min = 40 mm, max = 70 mm
rail_h = 8 mm
overhang = 15 mm
ear_d = 18 mm
ribbon_d = 5 mm

def chair_sign(word="Mr") -> solid {
    letters = Text(word, position=(0, 0), size=cap, font="serif:Bold")
    rail = Rectangle(corner=(letters.bb.left - overhang, -rail_h / 2),
                     opposite=(letters.bb.right + overhang, rail_h / 2))
    ear_l = Circle(center=(letters.bb.left - overhang, 0), diameter=ear_d)
    ear_r = Circle(center=(letters.bb.right + overhang, 0), diameter=ear_d)
    hole ribbon_l { c = Circle(center=(0, 0), diameter=ribbon_d) }
    hole ribbon_r { c = Circle(center=(0, 0), diameter=ribbon_d) }
    Concentric(ribbon_l.c, ear_l)
    Concentric(ribbon_r.c, ear_r)
}

assembly chair_signs {
    mr = chair_sign(word="Mr")
    mrs = chair_sign(word="Mrs")
    Below(mrs, mr, gap=10)
    AlignLeft(mrs, mr)

    assert mr.letters.size == 60 mm and mrs.letters.size == 60 mm, "60 mm cap height"
    assert mr.rail.bb.height == 8 mm, "rail 8 mm tall"
    assert mr.letters.bb.left - mr.rail.bb.left == 15 mm, "rail 15 mm past the letters"
    assert mr.ear_l.diameter == 18 mm and mr.ribbon_l.c.diameter == 5 mm, "18 mm ears, 5 mm holes"
    assert mr.bb.width <= 260 mm and mrs.bb.width <= 260 mm, "fits a chair back"
}
