# Request (sport): a wall bracket for a bike track pump, from 6 mm ply. A back plate 120 x
# 200 mm (R8) screwed to the wall with two countersunk 4 mm screws (4.5 mm holes, 9 mm heads)
# on the centre line 20 mm from top and bottom. A shelf arm 120 wide standing out 90 mm from
# the plate, its underside 150 mm up the plate, with a U notch 42 mm wide and 60 mm deep from
# its front edge for the pump's barrel (the handle rests on the arm). Under it two gussets,
# 45 mm either side of the centre, 80 mm along the wall and 80 mm along the arm, their
# outer edge a concave curve with 10 mm flats at each end. A J-hook for the hose, 20 mm tall,
# standing out 56 mm with a lip rising to 30 mm, its top 50 mm up the plate, 45 mm right of
# centre (clear of the barrel). All glued: 2 tabs 30 wide on the arm's back edge, 2 tabs 20
# wide on each gusset edge, 1 tab 12 wide for the hook. A bike outline engraved on the plate
# between the gussets.

import "std/joints.aidl"

thickness 6 mm

t = 6 mm
plate_w = 120 mm
plate_h = 200 mm
arm_z = 150 mm       # the arm's underside, up the plate
arm_d = 90 mm        # out from the plate
g_x = 45 mm          # gussets either side of the centre
g_l = 80 mm          # gusset legs
hook_x = 45 mm
hook_top = 50 mm

def gusset() -> solid {
    # x: out from the wall (the wall edge's tab tips at x = 0), y: up (the arm's underside at g_l)
    a = Line((0, 0), (0, g_l))
    b = Line((0, g_l), (t, g_l))
    c = Line((t, g_l), (t, g_l + t))
    d = Line((t, g_l + t), (t + g_l, g_l + t))
    e = Line((t + g_l, g_l + t), (t + g_l, g_l - 10 mm))
    f = Arc(start=(t + g_l, g_l - 10 mm), through=(t + 36.5 mm, 43.5), end=(t + 10 mm, 0))
    g = Line((t + 10 mm, 0), (0, 0))
    wall = tab_and_slot(part="tab", length=g_l, thickness=t, tabs=2, tab=20 mm, screw=0,
                        rotation=90 deg, cx=0 mm, cy=g_l / 2)
    top = tab_and_slot(part="tab", length=g_l, thickness=t, tabs=2, tab=20 mm, screw=0,
                       rotation=0 deg, cx=t + g_l / 2, cy=g_l + t)
}

assembly rack {
    solid back {
        plate = RoundedRectangle(corner=(-plate_w / 2, 0), opposite=(plate_w / 2, plate_h),
                                 corner_radius=8)
        hole screws {
            top = Circle(center=(0, plate_h - 20 mm), diameter=4.5)
            bottom = Circle(center=(0, 20), diameter=4.5)
        }
        Countersink(screws, diameter=9 mm)
        arm_slots = tab_and_slot(part="slot", length=plate_w, thickness=t, tabs=2, tab=30 mm,
                                 screw=0, rotation=0 deg, cx=0 mm, cy=arm_z + t / 2)
        left_slots = tab_and_slot(part="slot", length=g_l, thickness=t, tabs=2, tab=20 mm,
                                  screw=0, rotation=90 deg, cx=-g_x, cy=arm_z - g_l / 2)
        right_slots = tab_and_slot(part="slot", length=g_l, thickness=t, tabs=2, tab=20 mm,
                                   screw=0, rotation=90 deg, cx=g_x, cy=arm_z - g_l / 2)
        hook_slot = tab_and_slot(part="slot", length=20 mm, thickness=t, tabs=1, tab=12 mm,
                                 screw=0, rotation=90 deg, cx=hook_x, cy=hook_top - 10 mm)
        drawing bike {
            rear = Circle(center=(-20, 95), radius=12)
            front = Circle(center=(20, 95), radius=12)
            chain_stay = Line((-20, 95), (-3, 95))
            seat_tube = Line((-3, 95), (-8, 115))
            seat_stay = Line((-8, 115), (-20, 95))
            top_tube = Line((-8, 115), (13, 113))
            down_tube = Line((13, 113), (-3, 95))
            fork = Line((13, 113), (20, 95))
            stem = Line((13, 113), (14, 118))
            bars = Line((11, 118), (18, 118))
            saddle = Line((-13, 117), (-5, 117))
            post = Line((-8, 115), (-9, 117))
        }
    }

    solid arm {
        # x across, y out from the wall: the back edge's tab tips at y = 0, the front at t + arm_d
        board = Rectangle(corner=(-plate_w / 2, 0), opposite=(plate_w / 2, t + arm_d))
        tabs = tab_and_slot(part="tab", length=plate_w, thickness=t, tabs=2, tab=30 mm, screw=0,
                            rotation=180 deg, cx=0 mm, cy=0 mm)
        hole barrel {
            u = Slot(start=(0, t + arm_d - 60 mm + 21 mm), end=(0, t + arm_d + 30 mm), width=42)
        }
        left_slots = tab_and_slot(part="slot", length=g_l, thickness=t, tabs=2, tab=20 mm,
                                  screw=0, rotation=90 deg, cx=-g_x, cy=t + g_l / 2)
        right_slots = tab_and_slot(part="slot", length=g_l, thickness=t, tabs=2, tab=20 mm,
                                   screw=0, rotation=90 deg, cx=g_x, cy=t + g_l / 2)
    }

    left = gusset()
    right = gusset()

    solid hook {
        # x out from the wall (tab tip at 0), y up
        j = Polygon([(0, 0), (t + 50 mm, 0), (t + 50 mm, 30), (t + 40 mm, 30), (t + 40 mm, 20),
                     (0, 20)])
        Fillet(j.points[1], 6)
        Fillet(j.points[2], 4)
        Fillet(j.points[3], 3)
        tab = tab_and_slot(part="tab", length=20 mm, thickness=t, tabs=1, tab=12 mm, screw=0,
                           rotation=90 deg, cx=0 mm, cy=10 mm)
    }

    # flat on the sheet
    RightOf(arm, back, gap=8)
    AlignTop(arm, back)
    Below(left, arm, gap=8)
    AlignLeft(left, arm)
    RightOf(right, left, gap=8)
    AlignTop(right, left)
    Below(hook, left, gap=8)
    AlignLeft(hook, left)

    # assembled: the wall behind (+y), the plate's front face at y = 0
    Place(back, position=(0, t, 0), face="front", up="up")
    Place(arm, position=(0, t, arm_z), face="up", up="front")
    Place(right, position=(g_x + t / 2, t, arm_z - g_l), face="left", up="up")
    Place(left, position=(-g_x + t / 2, t, arm_z - g_l), face="left", up="up")
    Place(hook, position=(hook_x + t / 2, t, hook_top - 20 mm), face="left", up="up")

    assert back.plate.bb.width == 120 mm and back.plate.bb.height == 200 mm, "plate 120 x 200"
    assert back.plate.bb.top - back.screws.top.center.y == 20 mm, "top screw 20 from the top"
    assert back.screws.bottom.center.y - back.plate.bb.bottom == 20 mm, "bottom screw 20 up"
    assert arm.board.bb.height - t == 90 mm, "arm stands out 90"
    assert arm.board.bb.top - arm.barrel.u.bb.bottom == 60 mm, "U notch 60 deep"
    assert arm.barrel.u.width == 42 mm, "U notch 42 wide"
    assert back.arm_slots.slot[0].bb.bottom - back.plate.bb.bottom == 150 mm, "arm at 150"
    assert back.right_slots.slot[0].center.x - back.plate.bb.center_x == 45 mm, "gusset at 45"
    assert back.hook_slot.slot[0].center.y + 10 mm - back.plate.bb.bottom == 50 mm, "hook top at 50"
    assert hook.j.bb.width - t == 50 mm and hook.j.bb.height == 30 mm, "hook 56 out, lip 30"
    assert distance(back.bike, back.left_slots) >= 3 mm and distance(back.bike, back.right_slots) >= 3 mm,
        "bike clear of the gusset slots"
}
