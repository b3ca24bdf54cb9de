# Table-tennis bat blade (sport): 5 mm plywood. An oval blade 150 mm wide, 158 mm tall; a
# straight-tapered handle 100 mm long below the blade (28 mm wide at its end, 34 mm where it
# meets the blade), its end corners R6, the two inside corners where handle and blade meet
# rounded R8; overall length 258 mm. "SPIN" in sans Bold 9 mm high engraved (filled) along
# the handle, reading upward, centred on the handle, 50 mm below the blade. A 5 mm lanyard hole
# centred across, 10 mm above the handle's end.
units mm
thickness 5 mm

solid bat {
    blade = Ellipse(center=(0, 0), rx=75, ry=79)
    # the handle reaches 10 mm into the blade so that the two merge
    handle = Trapezoid(center=(0, -79 - 45), bottom_width=28, top_width=34, height=110)
    Fillet([handle.bottom_left, handle.bottom_right], 6)
    Fillet([handle.left, blade], 8)
    Fillet([handle.right, blade], 8)

    hole lanyard { c = Circle(center=(0, -169), diameter=5) }

    drawing logo {
        word = Text("SPIN", (0, -79 - 50), size=9, font="sans:Bold", fill=true, rotation=90 deg, valign="middle")
    }

    assert blade.bb.width == 150 mm and blade.bb.height == 158 mm, "blade 150 x 158"
    assert blade.bb.bottom - handle.bb.bottom == 100 mm, "handle 100 long below the blade"
    assert blade.bb.top - handle.bb.bottom == 258 mm, "overall 258"
    assert handle.bottom_width == 28 mm, "28 at the end"
    assert lanyard.c.center.y - handle.bb.bottom == 10 mm, "lanyard 10 above the end"
    assert blade.bb.bottom - logo.word.center.y == 50 mm, "logo 50 below the blade"
}
