# Request (bathroom): a square box that hides the plastic pot of a toilet brush, 110 x 110 mm
# and 140 mm tall outside, finger-jointed from 4 mm ply (12 mm fingers). The lid is left
# unglued so the pot can be lifted out: it has a 38 mm hole in the middle for the brush
# handle and two 25 x 10 mm finger slots 35 mm either side of the hole's centre to lift it by.
# The front is engraved with three wavy lines 80 mm wide, 12 mm apart, centred on the panel.

units mm
thickness 4 mm
import "std/joints.aidl"

assembly brush_box {
    box = finger_box(length=110 mm, depth=110 mm, height=140 mm, thickness=4 mm,
                     finger=12 mm, closed=true)

    hole handle { c = Circle(center=(0, 0), diameter=38) }
    CenterInside(handle, box.lid)
    CutInto(handle, box.lid)

    hole lifts {
        a = Slot(center=(0, 35), length=25, width=10)
        b = Slot(center=(0, -35), length=25, width=10)
    }
    CenterInside(lifts, box.lid)
    CutInto(lifts, box.lid)

    drawing waves {
        for i in range(3) {
            w = Spline([(-40, i * 12), (-20, i * 12 + 5), (0, i * 12), (20, i * 12 - 5),
                        (40, i * 12)])
        }
    }
    CenterInside(waves, box.front)
    CutInto(waves, box.front)

    # the request's numbers
    assert handle.c.diameter == 38 mm, "38 mm handle hole"
    assert lifts.a.center.y - handle.c.center.y == 35 mm, "lift slot 35 from the hole"
    assert handle.c.center.y - lifts.b.center.y == 35 mm, "lift slot 35 from the hole"
    assert lifts.a.bb.bottom - handle.c.bb.top >= 3 mm, "wall between slot and hole"
    assert box.lid.bb.top - lifts.bb.top >= 4 mm + 5 mm, "slots clear of the finger slots"
    assert len(waves.w) == 3, "three waves"
    assert waves.w[1].points[0].y - waves.w[0].points[0].y == 12 mm, "12 mm apart"
    assert waves.w[0].points[-1].x - waves.w[0].points[0].x == 80 mm, "80 mm wide"
}
