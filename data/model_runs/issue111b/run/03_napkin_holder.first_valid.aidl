# Napkin holder, 3 mm plywood, finger-jointed (10 mm fingers): a base 160 x 60 mm whose two
# long edges take the fingers of two upright sides 160 x 100 mm (fingers along each side's
# bottom edge, the other side edges flat). Each side has a stadium window 110 x 40 mm centered
# left-right, its center 55 mm above the side's bottom edge, and the front side has "NAPKINS"
# engraved 8 mm tall centered 20 mm above its bottom edge. Parts laid out 5 mm apart.

import "std/joints.aidl"

units mm
thickness 3 mm

param length = 160 mm, min = 120 mm, max = 250 mm
param depth = 60 mm, min = 40 mm, max = 100 mm
param side_h = 100 mm, min = 70 mm, max = 150 mm
param t = 3 mm, min = 2 mm, max = 6 mm

assembly napkin_holder {
    solid base {
        p = finger_panel(width=length, height=depth, thickness=t, finger=10 mm,
                         bottom="slots", top="slots", left="flat", right="flat")
    }

    solid front {
        p = finger_panel(width=length, height=side_h, thickness=t, finger=10 mm,
                         bottom="fingers", top="flat", left="flat", right="flat")
        hole window {
            w = Slot(center=(0, 0), length=110, width=40)
        }
        drawing label {
            word = Text("NAPKINS", position=(0, 0), size=8, valign="middle")
        }
        AlignCenterX(window, p.outline)
        window.w.center.y == p.outline.bb.bottom + 55 mm
        AlignCenterX(label, p.outline)
        label.word.position.y == p.outline.bb.bottom + 20 mm
    }

    solid back {
        p = finger_panel(width=length, height=side_h, thickness=t, finger=10 mm,
                         bottom="fingers", top="flat", left="flat", right="flat")
        hole window {
            w = Slot(center=(0, 0), length=110, width=40)
        }
        AlignCenterX(window, p.outline)
        window.w.center.y == p.outline.bb.bottom + 55 mm
    }

    Above(front, base, gap=5 mm)
    AlignCenterX(front, base)
    Above(back, front, gap=5 mm)
    AlignCenterX(back, base)

    assert abs(base.p.outline.width - 160 mm) < 0.001 mm and abs(base.p.outline.height - 60 mm) < 0.001 mm, "base 160 x 60 mm"
    assert abs(front.p.outline.width - 160 mm) < 0.001 mm and abs(front.p.outline.height - 100 mm) < 0.001 mm, "side 160 x 100 mm"
    assert abs(front.window.w.length - 110 mm) < 0.001 mm and abs(front.window.w.width - 40 mm) < 0.001 mm, "window 110 x 40 mm"
    assert abs(back.window.w.center.y - back.p.outline.bb.bottom - 55 mm) < 0.001 mm, "window 55 mm up"
    assert abs(front.label.word.size - 8 mm) < 0.001 mm, "label 8 mm tall"
}
