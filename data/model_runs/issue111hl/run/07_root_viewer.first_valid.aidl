# Request (science): a root viewer for the class's bean experiment. An open-top finger-
# jointed box 200 x 60 x 250 mm tall (outside, 3 mm, 10 mm fingers); the front panel is
# cut from clear acrylic, the rest from ply. A divider makes two compartments (bean A
# watered, bean B not): 230 mm tall above the box's floor, glued with two 12 mm tabs into
# the bottom and two 20 mm tabs into the back. Six 5 mm drain holes in the bottom, three
# per compartment (25, 50, 75 mm from the middle). Engraved on the front: a scale down the
# left side from the soil line (20 mm below the rim) 200 mm down: ticks every 5 mm, long
# ones every 10 mm numbered 0 to 20 (cm); "A WET" and "B DRY" over the two compartments,
# 6 mm high, 12 mm below the rim.

units mm
thickness 3 mm

import "std/joints.aidl"

t = 3 mm
inner_d = 60 mm - 2 * t     # front to back, inside
div_h = 230 mm

assembly root_viewer {
    box = finger_box(length=200 mm, depth=60 mm, height=250 mm, thickness=t, finger=10 mm,
                     closed=false)

    hole bottom_cuts {
        j = tab_and_slot(part="slot", length=inner_d, thickness=t, tabs=2, tab=12 mm, screw=0,
                         rotation=90 deg, cx=0 mm, cy=0 mm)
        for k in range(3) {
            dl = Circle(center=(-(k + 1) * 25 mm, 0), diameter=5)
            dr = Circle(center=((k + 1) * 25 mm, 0), diameter=5)
        }
    }
    CenterInside(bottom_cuts, box.bottom)
    CutInto(bottom_cuts, box.bottom)

    hole back_cuts {
        j = tab_and_slot(part="slot", length=div_h, thickness=t, tabs=2, tab=20 mm, screw=0,
                         rotation=90 deg, cx=0 mm, cy=0 mm)
    }
    AlignCenterX(back_cuts, box.back)
    back_cuts.bb.center_y == box.back.bb.bottom + t + div_h / 2
    CutInto(back_cuts, box.back)

    drawing scale {
        for k in range(41) {
            tick = Line((0, -k * 5 mm), ((8 if k % 2 == 0 else 4), -k * 5 mm))
        }
        for c in range(21) {
            num = Text(str(c), (11, -c * 10 mm), size=4, anchor="start", valign="middle")
        }
    }
    scale.bb.left == box.front.core.bb.left + 4 mm
    scale.tick[0].start.y == box.front.bb.top - 20 mm
    CutInto(scale, box.front)

    drawing labels {
        a = Text("A WET", (-48, 0), size=6, valign="top")
        b = Text("B DRY", (48, 0), size=6, valign="top")
    }
    AlignCenterX(labels, box.front)
    labels.a.position.y == box.front.bb.top - 12 mm
    CutInto(labels, box.front)

    solid divider {
        foot = Rectangle(bottom_left=(0, -t), width=inner_d, height=div_h + t)
        spine = Rectangle(bottom_left=(0, 0), width=inner_d + t, height=div_h)
        jb = tab_and_slot(part="tab", length=inner_d, thickness=t, tabs=2, tab=12 mm, screw=0,
                          rotation=180 deg, cx=inner_d / 2, cy=-t)
        jk = tab_and_slot(part="tab", length=div_h, thickness=t, tabs=2, tab=20 mm, screw=0,
                          rotation=270 deg, cx=inner_d + t, cy=div_h / 2)
    }
    RightOf(divider, box, gap=10)
    AlignBottom(divider, box)
    # assembled: across the box's middle, from the front's inner face to the back
    Place(divider, position=(-t / 2, -30 mm + t, t), face="right", up="up")

    # the request's numbers
    assert box.length == 200 mm and box.depth == 60 mm and box.height == 250 mm, "200 x 60 x 250"
    assert divider.spine.height == 230 mm, "divider 230 mm tall"
    assert len(bottom_cuts.dl) + len(bottom_cuts.dr) == 6, "six drain holes"
    assert bottom_cuts.dr[0].diameter == 5 mm, "5 mm drains"
    assert bottom_cuts.dr[2].center.x - bottom_cuts.j.slot[0].bb.center_x == 75 mm, "drains to 75 mm"
    assert box.front.bb.top - scale.tick[0].start.y == 20 mm, "soil line 20 mm below the rim"
    assert scale.tick[0].start.y - scale.tick[40].start.y == 200 mm, "scale 200 mm long"
    assert len(scale.tick) == 41 and len(scale.num) == 21, "ticks every 5 mm, numbers 0-20"
    assert box.front.bb.top - labels.a.position.y == 12 mm, "labels 12 mm below the rim"
    assert distance(scale, labels) >= 3 mm, "scale clear of the labels"
    assert labels.b.position.x - labels.a.position.x == 96 mm, "labels over the compartments"
}
