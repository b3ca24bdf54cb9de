# Pets: a memorial plaque for a dog, 5 mm walnut plywood, 180 x 120 mm, corners R15.
# The name "BISCUIT" engraved filled in sans Bold, 20 mm high, centred left-right, its
# middle 32 mm above the plaque's centre. "2012 - 2026" engraved in stroke text 7 mm
# high, centred, baseline 8 mm above the centre. A paw print cut through, centred
# left-right: a main pad (ellipse 24 x 18 mm) whose centre is 32 mm below the
# plaque's centre, and four toes (ellipses 8 x 10 mm) above it, the outer two tilted
# 20 deg outward. Two 4 mm screw holes countersunk 8 mm, 15 mm in from the left and
# right edges, at mid height.

units mm
thickness 5 mm

solid plaque {
    body = RoundedRectangle(center=(0, 0), width=180, height=120, corner_radius=15)

    drawing name {
        word = Text("BISCUIT", (0, 32), size=20, font="sans:Bold", fill=true, valign="middle")
    }
    drawing dates {
        line = Text("2012 - 2026", (0, 8), size=7)
    }

    hole paw {
        pad = Ellipse(center=(0, -32), rx=12, ry=9)
        toe1 = Ellipse(center=(-15, -18), rx=4, ry=5, rotation=20 deg)
        toe2 = Ellipse(center=(-5.5, -13), rx=4, ry=5)
        toe3 = Ellipse(center=(5.5, -13), rx=4, ry=5)
        toe4 = Ellipse(center=(15, -18), rx=4, ry=5, rotation=-20 deg)
    }

    hole screws {
        left = Circle(center=(-75, 0), diameter=4)
        right = Circle(center=(75, 0), diameter=4)
    }
    Countersink(screws, diameter=8 mm)

    # the request's numbers
    assert body.width == 180 mm and body.height == 120 mm, "180 x 120"
    assert name.word.size == 20 mm, "name 20 mm high"
    assert name.bb.center_y - body.center.y == 32 mm, "name's middle 32 above the centre"
    assert name.bb.center_x == body.center.x, "name centred"
    assert name.bb.width < body.width - 2 * 25 mm, "name clear of the screws"
    assert dates.line.size == 7 mm, "dates 7 mm"
    assert dates.line.position.y - body.center.y == 8 mm, "dates' baseline 8 above the centre"
    assert body.center.y - paw.pad.center.y == 32 mm, "pad 32 below the centre"
    assert paw.pad.rx == 12 mm and paw.pad.ry == 9 mm, "pad 24 x 18"
    assert paw.toe2.rx == 4 mm and paw.toe2.ry == 5 mm, "toes 8 x 10"
    assert paw.bb.center_x == body.center.x, "paw centred"
    assert paw.bb.top < dates.bb.bottom - 5 mm, "paw clear of the dates"
    assert paw.bb.bottom > body.bb.bottom + 10 mm, "paw inside the plaque"
    assert screws.left.diameter == 4 mm, "4 mm screws"
    assert screws.left.center.x - body.bb.left == 15 mm, "15 in from the left"
    assert body.bb.right - screws.right.center.x == 15 mm, "15 in from the right"
    assert screws.left.center.y == body.center.y, "at mid height"
}
