# Request: a thumb page holder for reading a paperback one-handed, cut from 3 mm walnut ply.
# 80 mm across overall: a round middle 32 mm across with a 22 mm thumb hole, and two wings
# that taper to rounded tips 14 mm across and sweep up 4 mm at the tips so they press the
# pages down either side of the spine. A 3 mm hole in the left tip for a tassel, "READ"
# engraved on the left wing and "ON" on the right wing.

units mm
thickness 3 mm

param span = 80 mm, min = 60 mm, max = 110 mm
param thumb_d = 22 mm, min = 18 mm, max = 26 mm
param middle_d = 32 mm, min = 28 mm, max = 40 mm
param tip_d = 14 mm, min = 10 mm, max = 18 mm
param sweep = 4 mm, min = 0 mm, max = 8 mm

solid page_holder {
    middle = Circle(center=(0, 0), diameter=middle_d)
    tip_l = Circle(center=(-(span - tip_d) / 2, sweep), diameter=tip_d, construction=true)
    wing_l = Hull(middle, tip_l)
    axis = Line((0, -20), (0, 20), construction=true)
    wing_r = Mirrored(wing_l, axis)

    hole thumb {
        c = Circle(center=(0, 0), diameter=thumb_d)
    }
    hole tassel {
        c = Circle(center=(-(span - tip_d) / 2, sweep), diameter=3)
    }
    drawing words {
        read = Text("READ", position=(-23, 2), size=4.5, valign="middle")
        on = Text("ON", position=(23, 2), size=4.5, valign="middle")
    }

    assert self.bb.width == 80 mm, "80 mm across"
    assert thumb.c.diameter == 22 mm, "22 mm thumb hole"
    assert tip_l.center.y - middle.center.y == 4 mm, "tips sweep up 4 mm"
    assert tassel.c.diameter == 3 mm, "3 mm tassel hole"
}
