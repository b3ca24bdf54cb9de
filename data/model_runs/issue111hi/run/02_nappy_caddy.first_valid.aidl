# Request (bathroom / nursery): a nappy caddy in 6 mm birch ply. An open-top
# finger-jointed box 300 mm long, 200 mm deep and 120 mm tall outside (20 mm
# fingers), split lengthwise by a carrying divider down the middle: the divider
# fills the 288 mm between the end walls, rises to 205 mm above the box's
# underside with its top narrowing to 200 mm long (20 mm radii at the top
# corners), and has a 100 x 30 mm hand hole with round ends whose top is 20 mm
# below the divider's top. The divider is glued in with three 40 mm tabs into
# the bottom and one 40 mm tab into each end wall (0.1 mm clearance in the
# mortises). The baby's name "ARLO" is engraved filled in bold sans, 40 mm
# letters, in the middle of the front.

import "std/joints.aidl"

t = 6 mm
thickness t

assembly caddy {
    box = finger_box(length=300 mm, depth=200 mm, height=120 mm, thickness=t,
                     finger=20 mm, closed=false)

    solid divider {
        shape = Polygon([(-150, 0), (150, 0), (150, 120), (100, 205), (-100, 205), (-150, 120)])
        Fillet([shape.points[3], shape.points[4]], 20)
        feet = tab_and_slot(part="tab", length=300 mm, thickness=t, tabs=3, tab=40 mm,
                            screw=0, rotation=180 deg, cx=0 mm, cy=0 mm)
        left_tab = tab_and_slot(part="tab", length=120 mm, thickness=t, tabs=1, tab=40 mm,
                                screw=0, rotation=90 deg, cx=-150 mm, cy=60 mm)
        right_tab = tab_and_slot(part="tab", length=120 mm, thickness=t, tabs=1, tab=40 mm,
                                 screw=0, rotation=-90 deg, cx=150 mm, cy=60 mm)
        hole grip {
            s = Slot(center=(0, 170), length=100, width=30)
        }
        assert shape.bb.height == 205 mm, "205 mm above the box's underside"
        assert shape.bb.top - grip.bb.top == 20 mm, "hand hole 20 mm below the top"
        assert grip.bb.width == 100 mm and grip.bb.height == 30 mm, "100 x 30 hand hole"
        assert len(feet.gap) == 4, "three tabs into the bottom"
    }

    # mortises for the divider: three in the bottom, one in each end wall
    hole bottom_mortise {
        m = tab_and_slot(part="slot", length=300 mm, thickness=t, tabs=3, tab=40 mm,
                         screw=0, clearance=0.1 mm)
    }
    CenterInside(bottom_mortise, box.bottom)
    CutInto(bottom_mortise, box.bottom)

    hole left_mortise {
        m = tab_and_slot(part="slot", length=120 mm, thickness=t, tabs=1, tab=40 mm,
                         screw=0, clearance=0.1 mm)
    }
    CenterInside(left_mortise, box.left)
    CutInto(left_mortise, box.left)

    hole right_mortise {
        m = tab_and_slot(part="slot", length=120 mm, thickness=t, tabs=1, tab=40 mm,
                         screw=0, clearance=0.1 mm)
    }
    CenterInside(right_mortise, box.right)
    CutInto(right_mortise, box.right)

    drawing name {
        word = Text("ARLO", position=(0, 0), size=40, valign="middle", font="sans:Bold", fill=true)
    }
    CenterInside(name, box.front)
    CutInto(name, box.front)

    RightOf(divider, box, gap=10)
    AlignBottom(divider, box)

    assert box.bottom.bb.width == 300 mm and box.bottom.bb.height == 200 mm, "300 x 200 outside"
    assert box.front.bb.height == 120 mm, "120 mm tall"
    assert divider.shape.bb.width == 300 mm, "the divider's tabs reach through both end walls"
}
