# Star cookie-cutter outlines, cut from 6 mm food-safe acrylic: a five-pointed
# star 80 mm across its tips (outer radius 40 mm, inner radius 17 mm), tips
# rounded with a 4 mm radius, as a cutting wall 2.5 mm thick outside the star
# outline. A second, small cutter is the same star scaled to 60 %, placed 8 mm to
# the right of the large one, centered on the same line.
# (fix: `Scale(small, 0.6)` left an 18.9 mm gap and a 1.1 mm vertical offset,
# so the small star is now made at 60 % by the template's factor `k`.)

units mm
thickness 6 mm
min_wall 0.5 mm

def star_cutter(k=1) -> solid {
    outline = Star(center=(0, 0), points=5, outer_radius=40 * k, inner_radius=17 * k,
                   tip_radius=4 * k, construction=true)
    wall = Shell(outline, 2.5 * k)
}

assembly cutters {
    large = star_cutter()
    small = star_cutter(k=0.6)
    RightOf(small, large, gap=8)
    AlignCenterY(small, large)
}
