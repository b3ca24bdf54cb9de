# Request: a lazy kate (bobbin stand for plying) for three spinning-wheel bobbins up to 120 mm
# long with 90 mm flanges, on 6 mm steel rods; 6 mm birch ply.
# - Two uprights 140 mm apart inside. Each is the convex hull of a 270 mm long foot and rounds
#   around the holes: three 6.5 mm rod holes stepping 90 mm along the depth (-90, 0, +90) and
#   35 mm up (55, 90, 125 mm above the base's top), R22 round each; a carrying handle mortise
#   at +90 mm along, 200 mm up, R30 round it. Three 30 mm glued tabs on each foot go through
#   mortises in the base. "LAZY KATE" engraved 10 mm high on the outside of each upright,
#   centred 10 mm behind the middle, baseline 20 mm above the base.
# - Base 180 x 290 mm, corners R10.
# - Handle bar 40 mm tall across the top, one 20 mm tenon through each upright, with a
#   90 x 22 mm finger slot.
# The flanges must clear each other, the base and the handle by at least 5 mm.

import "std/joints.aidl"

thickness 6 mm

t = 6 mm
inside = 140 mm
foot = 270 mm
rod_y = [-90 mm, 0 mm, 90 mm]
rod_z = [55 mm, 90 mm, 125 mm]
hand_y = 90 mm
hand_z = 200 mm
flange_r = 45 mm

# an upright, y along the depth (s = -1: the mirror image, for the left one, so that its
# engraving reads on its outside), z = 0 at the base's top (the tabs' tips at z = -t)
def upright(s=1) -> solid {
    body = Hull(Rectangle(center=(0, (10 mm - t) / 2), width=foot, height=10 mm + t),
                Circle(center=(s * rod_y[0], rod_z[0]), radius=22),
                Circle(center=(s * rod_y[1], rod_z[1]), radius=22),
                Circle(center=(s * rod_y[2], rod_z[2]), radius=22),
                Circle(center=(s * hand_y, hand_z), radius=30))
    hole rods {
        for i in range(3) {
            r = Circle(center=(s * rod_y[i], rod_z[i]), diameter=6.5)
        }
    }
    feet = tab_and_slot(part="tab", length=foot, thickness=t, tabs=3, tab=30 mm, screw=0,
                        rotation=180 deg, cx=0 mm, cy=-t)
    handle_m = tab_and_slot(part="slot", length=40 mm, thickness=t, tabs=1, tab=20 mm, screw=0,
                            rotation=90 deg, cx=s * hand_y, cy=hand_z)
    Fixed(body)
    Fixed(rods)
    drawing label {
        w = Text("LAZY KATE", position=(s * -10 mm, 20 mm), size=10 mm)
    }
}

assembly lazy_kate {
    right = upright(s=1)
    left = upright(s=-1)

    solid base {
        body = RoundedRectangle(center=(0, 0), width=180, height=290, corner_radius=10)
        r_m = tab_and_slot(part="slot", length=foot, thickness=t, tabs=3, tab=30 mm, screw=0,
                           rotation=90 deg, cx=inside / 2 + t / 2, cy=0 mm)
        l_m = tab_and_slot(part="slot", length=foot, thickness=t, tabs=3, tab=30 mm, screw=0,
                           rotation=90 deg, cx=-(inside / 2 + t / 2), cy=0 mm)
        Fixed(body)
    }

    solid handle {
        body = Rectangle(center=(0, 0), width=inside + 2 * t, height=40)
        r_t = tab_and_slot(part="tab", length=40 mm, thickness=t, tabs=1, tab=20 mm, screw=0,
                           rotation=-90 deg, cx=inside / 2 + t, cy=0 mm)
        l_t = tab_and_slot(part="tab", length=40 mm, thickness=t, tabs=1, tab=20 mm, screw=0,
                           rotation=90 deg, cx=-(inside / 2 + t), cy=0 mm)
        hole grip { s = Slot(center=(0, 0), length=90, width=22) }
        Fixed(body)
    }

    # on the sheet
    RightOf(left, right, gap=6)
    AlignBottom(left, right)
    Below(base, right, gap=6)
    AlignLeft(base, right)
    RightOf(handle, base, gap=6)
    AlignTop(handle, base)

    # in 3D: x along the rods, y the depth, z up from the table
    Place(base, position=(0, 0, 0), face="up")
    Place(right, position=(inside / 2, 0, t), face="right", up="up")
    Place(left, position=(-inside / 2, 0, t), face="left", up="up")
    Place(handle, position=(0, hand_y - t / 2, t + hand_z), face="back", up="up")

    assert base.body.bb.width == 180 mm and base.body.bb.height == 290 mm, "base 180 x 290"
    assert handle.body.bb.width - 2 * t == 140 mm, "140 inside"
    assert rod_y[1] - rod_y[0] == 90 mm and rod_z[1] - rod_z[0] == 35 mm, "steps 90 along, 35 up"
    assert right.rods.r[0].diameter == 6.5 mm, "6.5 mm rod holes"
    assert handle.grip.s.length == 90 mm and handle.grip.s.width == 22 mm, "90 x 22 grip"
    # bobbin flanges: from each other, the base, the handle bar
    assert sqrt((rod_y[1] - rod_y[0]) ** 2 + (rod_z[1] - rod_z[0]) ** 2) - 2 * flange_r >= 5 mm,
        "flanges clear each other"
    assert rod_z[0] - flange_r >= 5 mm, "flanges clear the base"
    assert (hand_z - 20 mm) - (rod_z[2] + flange_r) >= 5 mm, "flange clears the handle"
    assert abs(rod_y[0]) + flange_r <= 145 mm, "the base covers the flanges"
}
