# Request (workshop): a stand that keeps three 250 ml wood-glue bottles upside down, so the glue
# waits at the nozzle. 3 mm plywood, an open-fronted box 200 mm long, 70 mm deep, 80 mm tall:
# a top plate 200 x 70 with three 36 mm holes for the bottle shoulders on 60 mm centres (the
# middle one centred), a bottom plate 200 x 70 that catches drips, and two end panels 70 x 80
# finger-jointed (10 mm fingers) to the top and bottom. Each end has a 50 x 18 mm hand slot whose
# top is 12 mm below the panel's top, and "GLUE" engraved as filled bold letters 14 mm tall,
# centred, under the slot. Parts laid flat, 8 mm apart, for cutting.

import "std/joints.aidl"

thickness 3 mm

param length = 200 mm, min = 150 mm, max = 300 mm
param depth = 70 mm, min = 60 mm, max = 100 mm
param height = 80 mm, min = 60 mm, max = 120 mm
param bottle_d = 36 mm, min = 30 mm, max = 45 mm
param pitch = 60 mm, min = 45 mm, max = 90 mm

t = 3 mm

def end_panel() -> solid {
    p = finger_panel(width=depth, height=height, thickness=t, finger=10 mm,
                     top="slots", bottom="slots", left="flat", right="flat")
    hole grip {
        s = Slot(center=(0, 0), length=50, width=18)
    }
    AlignCenterX(grip, p.outline)
    grip.bb.top == p.outline.bb.top - 12 mm
    drawing label {
        word = Text("GLUE", (0, 0), size=14, font="sans:Bold", fill=true, valign="top")
    }
    AlignCenterX(label, p.outline)
    label.bb.top == grip.bb.bottom - 8 mm
}

assembly glue_stand {
    solid top {
        p = finger_panel(width=length, height=depth, thickness=t, finger=10 mm,
                         left="fingers", right="fingers", top="flat", bottom="flat")
        hole necks {
            for i in range(3) {
                c = Circle(center=((i - 1) * pitch, 0), diameter=bottle_d)
            }
        }
        CenterInside(necks, p.outline)
    }
    solid bottom {
        p = finger_panel(width=length, height=depth, thickness=t, finger=10 mm,
                         left="fingers", right="fingers", top="flat", bottom="flat")
    }
    left_end = end_panel()
    right_end = end_panel()

    Below(bottom, top, gap=8)
    AlignLeft(bottom, top)
    RightOf(left_end, top, gap=8)
    AlignTop(left_end, top)
    RightOf(right_end, left_end, gap=8)
    AlignTop(right_end, left_end)

    # the request's numbers
    assert len(top.necks.c) == 3, "three bottle holes"
    assert abs(top.necks.c[0].diameter - 36 mm) < 0.01 mm, "36 mm holes"
    assert abs(top.necks.c[1].center.x - top.necks.c[0].center.x - 60 mm) < 0.01 mm, "60 mm centres"
    assert abs(top.necks.c[1].center.x - top.p.outline.center.x) < 0.01 mm, "middle hole centred"
    assert abs(top.p.outline.width - 200 mm) < 0.01 mm and abs(top.p.outline.height - 70 mm) < 0.01 mm, "top 200 x 70"
    assert abs(left_end.p.outline.height - 80 mm) < 0.01 mm, "80 mm tall"
    assert abs(left_end.p.outline.bb.top - left_end.grip.bb.top - 12 mm) < 0.01 mm, "slot 12 mm below the top"
    assert left_end.label.bb.bottom > left_end.p.outline.bb.bottom + 3 mm, "label on the panel"
}
