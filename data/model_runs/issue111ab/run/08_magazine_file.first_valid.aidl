# Request (office): an A4 magazine file, 3 mm ply, finger-jointed and glued. Outside: 240 mm
# deep, 90 mm wide, 300 mm tall at the back, 110 mm tall at the front; each side's top runs
# level for 50 mm from the back, then slopes straight down to the front's top (the corner
# at the top of the slope rounded R20). Five panels: two sides, a bottom 240 x 90, a front
# 90 x 110, a back 90 x 300 with a 25 mm finger hole centred 30 mm below its top. Fingers
# about 10 mm: the sides carry the fingers on their bottom, front and back edges (and keep
# the corner squares); the bottom carries fingers into the front and the back; the front and
# back tops are plain. The left side has "INVOICES" engraved as filled letters (sans bold,
# 20 mm), centred 60 mm above the bottom and 130 mm from the front.

units mm
thickness 3 mm
kerf 0.15 mm

import "std/joints.aidl"

t = 3 mm
depth = 240 mm
wide = 90 mm
back_h = 300 mm
front_h = 110 mm
level = 50 mm
fing = 10 mm

def side(label="") -> solid {
    shape = Polygon([(0, 0), (depth, 0), (depth, back_h), (depth - level, back_h),
                     (0, front_h)])
    bottom_j = finger_edge(length=depth - 2 * t, thickness=t, finger=fing, start="tab",
                           rotation=180 deg, cx=depth / 2, cy=0 mm)
    front_j = finger_edge(length=front_h - 2 * t, thickness=t, finger=fing, start="tab",
                          rotation=90 deg, cx=0 mm, cy=front_h / 2)
    back_j = finger_edge(length=back_h - 2 * t, thickness=t, finger=fing, start="tab",
                         rotation=-90 deg, cx=depth, cy=back_h / 2)
    Fillet(shape.points[3], 20)
    if label != "" {
        drawing name {
            word = Text(label, position=(130, 60), size=20, font="sans:Bold",
                        valign="middle", fill=true)
        }
    }
}

assembly magazine_file {
    left = side(label="INVOICES")
    right = side()
    bottom = finger_panel(width=depth, height=wide, thickness=t, finger=fing,
                          bottom="slots", right="fingers", top="slots", left="fingers")
    front = finger_panel(width=wide, height=front_h, thickness=t, finger=fing,
                         bottom="slots", right="slots", top="flat", left="slots")
    solid back {
        panel = finger_panel(width=wide, height=back_h, thickness=t, finger=fing,
                             bottom="slots", right="slots", top="flat", left="slots")
        hole pull {
            c = Circle(center=(0, 0), diameter=25)
        }
        AlignCenterX(pull, panel)
        pull.c.center.y == panel.outline.bb.top - 30 mm
    }

    RightOf(right, left, gap=10)
    AlignBottom(right, left)
    RightOf(back, right, gap=10)
    AlignBottom(back, left)
    Below(bottom, left, gap=10)
    AlignLeft(bottom, left)
    RightOf(front, bottom, gap=10)
    AlignTop(front, bottom)

    assert abs(left.shape.bb.width - 240 mm) < 0.01, "240 deep"
    assert abs(left.shape.bb.height - 300 mm) < 0.01, "300 tall at the back"
    assert abs(left.shape.points[4].y - left.shape.points[0].y - 110 mm) < 0.01, "110 at the front"
    assert abs(bottom.outline.bb.width - 240 mm) < 0.01 and abs(bottom.outline.bb.height - 90 mm) < 0.01, "bottom 240 x 90"
    assert abs(front.outline.bb.height - 110 mm) < 0.01, "front 110"
    assert abs(back.panel.outline.bb.height - 300 mm) < 0.01, "back 300"
    assert abs(back.pull.c.diameter - 25 mm) < 0.01, "25 mm finger hole"
    assert left.name.bb.left > left.shape.bb.left + 10 mm, "label on the side"
    assert left.name.bb.top < left.shape.points[4].y - 10 mm, "label below the front's top"
}
