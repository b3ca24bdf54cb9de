# Kitchen: a flat pancake spatula, 280 mm long overall, cut from 4 mm hardwood.
# Blade 100 mm long x 90 mm wide with R12 corners, three 60 x 6 mm drain slots along it
# (18 mm apart, centred in the blade); a 30 mm neck tapering from 50 mm to 26 mm, its
# joins to the blade rounded R6; a 150 mm handle 26 mm wide with a fully rounded end;
# an 8 mm hanging hole 15 mm from the handle's end; "PANCAKES" engraved 6 mm tall on the
# handle, centred between the neck and the hanging hole.

thickness 4 mm

solid spatula {
    blade = RoundedRectangle(center=(50, 0), width=100, height=90, corner_radius=12)
    neck = Trapezoid(center=(115, 0), bottom_width=50, top_width=26, height=30,
                     rotation=-90 deg)
    handle = RoundedRectangle(center=(205, 0), width=150, height=26,
                              corner_radii=[0, 13, 13, 0])
    RightOf(neck, blade)
    RightOf(handle, neck)
    AlignCenterY(neck, blade)
    AlignCenterY(handle, blade)

    hole slots {
        for i in range(3) {
            s = Slot(center=(50, -18 + i * 18), length=60, width=6)
        }
    }
    CenterInside(slots, blade)

    hole hang {
        c = Circle(center=(265, 0), diameter=8)
    }
    AlignCenterY(hang, handle)
    HorizontalDistance(hang.c.center, handle.right.midpoint, 15)

    drawing label {
        t = Text("PANCAKES", (200, 0), size=6, valign="middle")
    }
    AlignCenterY(label, handle)
    label.bb.center_x == (handle.bb.left + hang.bb.left) / 2

    Fillet([neck.bottom_left, neck.bottom_right], 6)
}

assert spatula.bb.width == 280 mm, "280 mm long overall"
assert spatula.blade.bb.width == 100 mm and spatula.blade.bb.height == 90 mm, "blade 100 x 90"
assert spatula.handle.bb.height == 26 mm and spatula.handle.bb.width == 150 mm, "handle 150 x 26"
assert spatula.neck.bb.width == 30 mm, "neck 30 mm"
assert len(spatula.slots.s) == 3, "three drain slots"
assert spatula.slots.s[1].center.y - spatula.slots.s[0].center.y == 18 mm, "slots 18 apart"
assert spatula.bb.right - spatula.hang.c.center.x == 15 mm, "hanging hole 15 from the end"
assert spatula.hang.c.diameter == 8 mm, "8 mm hanging hole"
