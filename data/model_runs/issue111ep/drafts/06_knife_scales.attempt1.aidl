# Request (camping): a pair of handle scales for my bushcraft knife blank (full tang,
# 3.2 mm steel), cut from 6 mm walnut ply. The tang, seen from the knife's right side with
# the spine up and the blade to the right, runs 113 mm back from a straight front edge
# 26 mm tall (spine 13 mm above the pin line, belly 13 mm below at the front); the spine is
# almost straight, the belly swells to 16.5 mm below the pin line 60 mm back, and the butt is
# rounded. Two 6 mm pin holes on the pin line at 25 and 75 mm behind the front edge and an
# 8 mm lanyard-tube hole at 100 mm. The right scale has my mark "HALVARD" (serif, 5 mm)
# engraved between the pins on its outer face; the left scale is its mirror image (the
# outline reversed front to back) so it too is cut face up, with no engraving.

units mm
t = 6 mm
thickness t
kerf 0.15 mm
tang = 3.2 mm

# the right side's outline: index 0 the front top corner, the last the front bottom corner
profile = [(0, 13), (30, 14), (60, 14.5), (90, 13.5), (106, 13), (112, 8), (113, 0),
           (111, -8), (102, -12), (80, -13.5), (60, -16.5), (35, -15), (12, -13.2), (0, -13)]
pins = [25 mm, 75 mm]
lanyard_x = 100 mm

def scale(s=1, mark=true) -> solid {
    outline = Spline([(s * p[0], p[1]) for p in profile], closed=true, corners=[0, 13])
    for k in range(2) {
        hole pin { c = Circle(center=(s * pins[k], 0), diameter=6) }
    }
    hole lanyard { c = Circle(center=(s * lanyard_x, 0), diameter=8) }
    if mark {
        drawing logo {
            word = Text("HALVARD", position=(s * 50, 0), size=5, font="serif", valign="middle")
        }
    }
}

assembly handle {
    right = scale(s=1, mark=true)
    left = scale(s=-1, mark=false)

    # cutting layout: the left scale under the right one
    Below(left, right, gap=6)
    AlignLeft(left, right)

    # in 3D: either side of the tang, each outer face outward, the blade toward +x
    Place(right, position=(0, -tang / 2, 0), face="front", up="up")
    Place(left, position=(0, tang / 2, 0), face="back", up="up")

    # the request's numbers
    assert profile[6][0] - profile[0][0] == 113 mm
    assert profile[0][1] - profile[13][1] == 26 mm
    assert profile[10][1] == -16.5 mm and profile[10][0] == 60 mm
    assert right.pin[0].c.center.x - right.outline.points[0].x == 25 mm
    assert right.pin[1].c.center.x - right.outline.points[0].x == 75 mm
    assert right.lanyard.c.center.x - right.outline.points[0].x == 100 mm
    assert right.pin[0].c.diameter == 6 mm and right.lanyard.c.diameter == 8 mm
    # the mirror: the left's holes as far behind its front edge, the other way
    assert left.outline.points[0].x - left.pin[1].c.center.x == 75 mm
    # the mark sits between the pins with 2 mm to spare each side
    assert right.logo.bb.left - (right.pin[0].c.center.x + 3 mm) >= 2 mm
    assert (right.pin[1].c.center.x - 3 mm) - right.logo.bb.right >= 2 mm
    # the lanyard hole leaves 3 mm of wood to the edge (the spine is lowest there at 13)
    assert 13 mm - 4 mm >= 3 mm and 12 mm - 4 mm >= 3 mm
}
