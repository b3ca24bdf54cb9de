# Request: a mic flag (the logo cube on a handheld interview microphone) for the podcast
# "NIGHT SHIFT", 3 mm black acrylic, finger-jointed and glued: a 60 mm cube outside. The top and
# bottom each have a 36 mm hole for the mic's handle. Front and back carry the name engraved
# filled in bold sans on two lines, "NIGHT" over "SHIFT", at most 46 mm wide, centred. The left
# and right sides each have a crescent moon cut through (outer circle 30 mm across, bitten by a
# 26 mm circle 7 mm off-centre, horns pointing sideways on the cube) and two small 5-point stars
# cut through (9 mm across the tips).

import "std/joints.aidl"

thickness 3 mm

param cube = 60 mm, min = 50 mm, max = 90 mm
mic_d = 36 mm

def logo() -> drawing {
    top = Text("NIGHT", position=(0, 2), size=11, font="sans:Bold", fill=true, max_width=46 mm)
    bottom = Text("SHIFT", position=(0, -13), size=11, font="sans:Bold", fill=true, max_width=46 mm)
}

# the crescent opens toward +y here: the sides lie on their side in the net, so +y is sideways
# on the finished cube
def moon_cut() -> hole {
    # both arcs counter-clockwise from the left horn to the right one (an Arc runs
    # counter-clockwise: written right to left, the outer one bent to another circle)
    outer = Arc(start=(-12.99, 7.5), through=(0, -15), end=(12.99, 7.5))
    inner = Arc(start=(-12.99, 7.5), through=(0, -6), end=(12.99, 7.5))
    Coincident(outer.start, inner.start)
    Coincident(outer.end, inner.end)
    star_a = Star(center=(17, 17), points=5, outer_radius=4.5, inner_radius=2)
    star_b = Star(center=(-17, 15), points=5, outer_radius=4.5, inner_radius=2)
    Rigid(self)
}

def mic_hole() -> hole {
    c = Circle(center=(0, 0), diameter=mic_d)
}

assembly mic_flag {
    box = finger_box(length=cube, depth=cube, height=cube, thickness=3 mm, finger=10 mm, closed=true)

    front_logo = logo()
    back_logo = logo()
    CenterInside(front_logo, box.front)
    CenterInside(back_logo, box.back)
    CutInto(front_logo, box.front)
    CutInto(back_logo, box.back)

    left_moon = moon_cut()
    right_moon = moon_cut()
    CenterInside(left_moon, box.left)
    CenterInside(right_moon, box.right)
    CutInto(left_moon, box.left)
    CutInto(right_moon, box.right)

    top_hole = mic_hole()
    bottom_hole = mic_hole()
    CenterInside(top_hole, box.lid)
    CenterInside(bottom_hole, box.bottom)
    CutInto(top_hole, box.lid)
    CutInto(bottom_hole, box.bottom)

    assert box.front.outline.width == 60 mm and box.front.outline.height == 60 mm, "60 mm cube"
    assert top_hole.c.diameter == 36 mm, "36 mm mic hole"
    assert front_logo.top.bb.width <= 46 mm and front_logo.bottom.bb.width <= 46 mm, "name at most 46 wide"
    assert left_moon.outer.radius == 15 mm and left_moon.inner.radius == 13 mm, "30 and 26 mm circles"
    assert left_moon.star_a.outer_radius * 2 == 9 mm, "stars 9 mm"
}
