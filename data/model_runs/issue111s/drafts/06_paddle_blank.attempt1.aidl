# Sport: a table-tennis paddle blank in 5 mm plywood (rubbers glued on later). Blade an ellipse
# 150 mm wide and 158 mm tall; a straight handle 25 mm wide from the bottom of the paddle up
# into the blade; overall length 258 mm. Handle end corners R5; the handle-blade junction
# rounded R8. A 5 mm lanyard hole on the centre line 10 mm above the handle's end. "CLUB 7" in
# sans outline letters, 8 mm, engraved on the handle-side of the blade, 20 mm above the
# blade's bottom.

thickness 5 mm
param blade_w = 150 mm, min = 140 mm, max = 160 mm
param blade_h = 158 mm, min = 150 mm, max = 165 mm
param overall = 258 mm, min = 240 mm, max = 270 mm

solid paddle {
    blade = Ellipse(center=(0, 179), rx=blade_w / 2, ry=blade_h / 2)
    handle = RoundedRectangle(bottom_left=(-12.5, 0), width=25, height=overall - blade_h + 20,
                              corner_radii=[0, 0, 5, 5])
    blade.center.y == handle.bb.bottom + overall - blade_h / 2
    AlignCenterX(blade, handle)

    hole lanyard {
        c = Circle(center=(0, 10), diameter=5)
    }
    lanyard.c.center.y == handle.bb.bottom + 10
    lanyard.c.center.x == handle.center.x

    drawing club {
        t = Text("CLUB 7", (0, 120), size=8, font="sans")
    }
    AlignCenterX(club, blade)
    club.bb.bottom == blade.bb.bottom + 20

    Fillet([handle.top_left, handle.top_right], 8)

    assert blade.bb.width == 150 mm and blade.bb.height == 158 mm, "blade 150 x 158"
    assert handle.bb.width == 25 mm, "handle 25 wide"
    assert max(blade.bb.top, handle.bb.top) - handle.bb.bottom == 258 mm, "258 overall"
    assert lanyard.c.center.y - handle.bb.bottom == 10 mm, "lanyard 10 up"
    assert club.bb.bottom - blade.bb.bottom == 20 mm, "text 20 above the blade's bottom"
}
