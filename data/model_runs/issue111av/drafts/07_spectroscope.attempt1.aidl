# Request: A pocket spectroscope for a school science club, from 3 mm black plywood: a closed
# finger-jointed box 150 mm long, 40 x 40 mm across (outside), 8 mm fingers. One end has the
# entrance slit, 1 mm wide and 20 mm long, upright and centred; the other end a 15 x 15 mm
# centred window for a piece of 1000 lines/mm diffraction grating film. A loose frame, 33 x 33 mm
# with the same 15 mm window, is glued inside the window end to clamp the film. Engrave
# "SPECTROSCOPE" 6 mm tall along the middle of the lid, and "SLIT" and "EYE" 4 mm tall on the
# outside of the two ends, 5 mm above their openings. Lay it out for cutting.

units mm
thickness 3 mm

import "std/joints.aidl"

param ply = 3 mm, min = 3 mm, max = 4 mm
param slit_w = 1 mm, min = 0.5 mm, max = 2 mm

assembly spectroscope {
    box = finger_box(length=150 mm, depth=40 mm, height=40 mm, thickness=ply, finger=8 mm,
                     closed=true)

    # the ends lie on their side when flat: the box's height runs along x, so an upright slit
    # is long in x here
    hole slit {
        s = Rectangle(center=(0, 0), width=20, height=slit_w)
    }
    CenterInside(slit, box.left)
    CutInto(slit, box.left)

    hole window {
        w = Rectangle(center=(0, 0), width=15, height=15)
    }
    CenterInside(window, box.right)
    CutInto(window, box.right)

    drawing title {
        t = Text("SPECTROSCOPE", position=(0, 0), size=6, valign="middle")
    }
    CenterInside(title, box.lid)
    CutInto(title, box.lid)

    # "SLIT" and "EYE" read upright on the standing box: turned with the ends' top edge,
    # which points outward (-x on the left end, +x on the right)
    drawing slit_label {
        t = Text("SLIT", position=(0, 0), size=4, valign="middle", rotation=-90 deg)
    }
    AlignCenterY(slit_label, box.left)
    slit_label.t.position.x == slit.bb.left - 5 mm - 2 mm
    CutInto(slit_label, box.left)

    drawing eye_label {
        t = Text("EYE", position=(0, 0), size=4, valign="middle", rotation=90 deg)
    }
    AlignCenterY(eye_label, box.right)
    eye_label.t.position.x == window.bb.right + 5 mm + 2 mm
    CutInto(eye_label, box.right)

    solid frame {
        plate = Rectangle(center=(0, 0), width=33, height=33)
        hole opening { w = Rectangle(center=(0, 0), width=15, height=15) }
        CenterInside(opening, plate)
    }
    RightOf(frame, box, gap=10)
    AlignBottom(frame, box)

    assert abs(slit.s.height - 1 mm) < 0.001 mm and abs(slit.s.width - 20 mm) < 0.001 mm, "slit 1 x 20"
    assert abs(window.w.width - 15 mm) < 0.001 mm and abs(window.w.height - 15 mm) < 0.001 mm, "window 15 x 15"
    assert abs(frame.plate.width - 33 mm) < 0.001 mm, "frame 33 x 33"
    assert frame.plate.width <= 40 mm - 2 * ply, "frame fits inside"
    assert abs(box.lid.bb.width - 150 mm) < 0.01 mm, "box 150 long"
    assert slit_label.bb.left > box.left.bb.left + 1 mm, "SLIT on its end"
    assert eye_label.bb.right < box.right.bb.right - 1 mm, "EYE on its end"
}
