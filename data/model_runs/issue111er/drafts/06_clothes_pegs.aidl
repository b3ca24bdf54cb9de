# Request: two clothes pegs for a camp washing line, 6 mm birch ply, each made of two
# identical jaws 75 long x 10 tall (seen from the side) held shut by a rubber band.
# - The grip face runs along the inner edge for the front 30 mm; a 5 mm round hole for
#   the line, 24 mm from the tip, half in each jaw.
# - A fulcrum bump (3 mm radius) centred 38 mm from the tip, its bottom level with the
#   grip face; behind the grip face the inner edge steps up 3 mm to the back end, so the
#   handles can be squeezed together 6 mm.
# - A notch 3 wide x 1.5 deep in the outer edge, 14 mm from the tip, holds the band.
# - The tip's outer corner rounded R2, both back corners R3.
# The two jaws of a peg face each other, inner edges touching.

units mm
t = 6 mm
thickness t
kerf 0.15 mm

jaw_l = 75 mm
jaw_h = 10 mm
grip = 30 mm
step = 3 mm

def jaw() -> solid {
    outline = Polygon([(0, 0), (grip, 0), (grip + 2 mm, step), (jaw_l, step), (jaw_l, jaw_h),
                       (0, jaw_h)])
    fulcrum = Circle(center=(38 mm, step), radius=3 mm)
    hole line { c = Circle(center=(24 mm, 0), diameter=5 mm) }
    hole band { r = Rectangle(center=(14 mm, jaw_h), width=3 mm, height=3 mm) }
    Fixed(outline)
    Fixed(fulcrum)
    Fixed(line)
    Fixed(band)
    Fillet(outline.points[5], 2 mm)
    Fillet([outline.points[3], outline.points[4]], 3 mm)
}

assembly pegs {
    a_top = jaw()
    a_bottom = jaw()
    b_top = jaw()
    b_bottom = jaw()

    # flat layout: four jaws in a column
    Above(a_bottom, a_top, gap=4)
    AlignLeft(a_bottom, a_top)
    Above(b_top, a_bottom, gap=4)
    AlignLeft(b_top, a_bottom)
    Above(b_bottom, b_top, gap=4)
    AlignLeft(b_bottom, b_top)

    # 3D: each peg's jaws meet at z = 0, the lower one turned over; peg b 20 mm behind
    Place(a_top, position=(0, t / 2, 0), face="front", up="up")
    Place(a_bottom, position=(0, t / 2, 0), face="back", up="down")
    Place(b_top, position=(0, 20 mm + t / 2, 0), face="front", up="up")
    Place(b_bottom, position=(0, 20 mm + t / 2, 0), face="back", up="down")

    # the request's numbers
    assert a_top.outline.bb.width == 75 mm and a_top.outline.bb.height == 10 mm
    assert a_top.line.c.diameter == 5 mm and a_top.line.c.center.x - a_top.outline.bb.left == 24 mm
    assert a_top.line.c.center.y == a_top.outline.bb.bottom, "half the line hole in each jaw"
    assert a_top.fulcrum.center.x - a_top.outline.bb.left == 38 mm and a_top.fulcrum.radius == 3 mm
    assert a_top.fulcrum.bb.bottom == a_top.outline.bb.bottom, "fulcrum level with the grip face"
    assert a_top.band.r.center.x - a_top.outline.bb.left == 14 mm
    assert a_top.outline.bb.top - a_top.band.r.bb.bottom == 1.5 mm and a_top.band.r.width == 3 mm
    assert 2 * step == 6 mm, "handles squeeze 6 mm"
    assert distance(a_top.line, a_top.fulcrum) >= 3 mm
}
