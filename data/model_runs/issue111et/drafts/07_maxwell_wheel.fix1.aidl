# Request: a Maxwell's wheel (yo-yo flywheel) demonstration for the school physics lab, all
# 6 mm birch ply, glued, no screws. Five parts:
# - a base 220 x 120 mm, R6 corners, with two mortises for each upright's two 15 mm feet, the
#   uprights' centre planes 180 mm apart (x = +-90 mm); "MAXWELL'S WHEEL" engraved 7 mm tall
#   along its front edge;
# - two uprights 60 mm wide and 300 mm tall (tab tips included), standing across the base's
#   depth, two 15 mm feet at the bottom and one 20 mm tenon at the top;
# - a crossbar 220 x 40 mm lying flat on the uprights' tops, with the tenons' mortises and two
#   3 mm string holes 40 mm either side of the centre;
# - the wheel: a 120 mm disc with an 8 mm hole for the dowel axle and six window slots (ring
#   segments 20 mm wide centred on radius 30 mm, 40 degrees long centre to centre) that leave
#   the mass in the rim; it hangs on its strings 180 mm above the floor.
# Mortises 0.2 mm over the tabs.

import "std/joints.aidl"

units mm
t = 6 mm
thickness t
kerf 0.15 mm

span = 180 mm          # between the uprights' centre planes
up_w = 60 mm
up_h = 300 mm
base_w = 220 mm
base_d = 120 mm
bar_d = 40 mm
fit = 0.2 mm

def upright() -> solid {
    board = Rectangle(bottom_left=(-up_w / 2, 0), width=up_w, height=up_h)
    feet = tab_and_slot(part="tab", length=up_w, thickness=t, tabs=2, tab=15 mm, screw=0,
                        rotation=180 deg, cx=0, cy=0)
    tenon = tab_and_slot(part="tab", length=up_w, thickness=t, tabs=1, tab=20 mm, screw=0,
                         cx=0, cy=up_h)
}

assembly maxwell_wheel {
    solid base {
        plate = RoundedRectangle(center=(0, 0), width=base_w, height=base_d, corner_radius=6)
        left_m = tab_and_slot(part="slot", length=up_w, thickness=t, tabs=2, tab=15 mm, screw=0,
                              clearance=fit, rotation=90 deg, cx=-span / 2, cy=0)
        right_m = tab_and_slot(part="slot", length=up_w, thickness=t, tabs=2, tab=15 mm, screw=0,
                               clearance=fit, rotation=90 deg, cx=span / 2, cy=0)
        drawing name {
            word = Text("MAXWELL'S WHEEL", position=(0, -base_d / 2 + 12 mm), size=7, valign="middle")
        }
        Fixed(plate)
    }
    left = upright()
    right = upright()
    solid crossbar {
        bar = Rectangle(center=(0, 0), width=base_w, height=bar_d)
        left_m = tab_and_slot(part="slot", length=up_w, thickness=t, tabs=1, tab=20 mm, screw=0,
                              clearance=fit, rotation=90 deg, cx=-span / 2, cy=0)
        right_m = tab_and_slot(part="slot", length=up_w, thickness=t, tabs=1, tab=20 mm, screw=0,
                               clearance=fit, rotation=90 deg, cx=span / 2, cy=0)
        hole strings {
            for sx in [-1, 1] { c = Circle(center=(sx * 40, 0), diameter=3) }
        }
    }
    solid wheel {
        disc = Circle(center=(0, 0), diameter=120)
        hole axle { c = Circle(center=(0, 0), diameter=8) }
        hole window {
            # FIX after the first valid program: W0504 + 6 x W0508, the windows' round ends (10 mm
            # past the end centres, 19 degrees at r 30) made each window 78 degrees long on a
            # 60 degree pitch: they ran together and cut the hub off the rim. Now 16 mm wide
            # (r 22 to 38) and 12 degrees centre to centre: about 43 degrees long, 9 mm spokes.
            w = ArcSlot(center=(0, 0), radius=30, start_angle=-6 deg, end_angle=6 deg, width=16)
        }
        windows = CircularPattern(window, 6, (0, 0))
    }

    # flat on the sheet
    Below(left, base, gap=8)
    AlignLeft(left, base)
    RightOf(right, left, gap=8)
    AlignTop(right, left)
    RightOf(crossbar, right, gap=8)
    AlignTop(crossbar, right)
    Below(wheel, crossbar, gap=8)
    AlignLeft(wheel, crossbar)

    # standing
    Place(base, position=(0, 0, 0))
    Place(left, position=(-span / 2 + t / 2, 0, 0), face="left", up="up")
    Place(right, position=(span / 2 - t / 2, 0, 0), face="right", up="up")
    Place(crossbar, position=(0, 0, up_h - t))
    Place(wheel, position=(0, t / 2, 180), face="front", up="up")

    assert base.plate.width == 220 mm and base.plate.height == 120 mm
    assert base.right_m.slot[0].bb.center_x - base.left_m.slot[0].bb.center_x == 180 mm
    assert crossbar.right_m.slot[0].bb.center_x - crossbar.left_m.slot[0].bb.center_x == 180 mm
    assert base.right_m.slot[0].bb.width == 6 mm + 0.2 mm, "mortise 0.2 over the 6 mm tab"
    assert base.right_m.slot[0].bb.height == 15 mm + 0.2 mm
    assert crossbar.right_m.slot[0].bb.height == 20 mm + 0.2 mm
    assert left.board.width == 60 mm and left.board.height == 300 mm
    assert len(left.feet.gap) == 3 and len(left.tenon.gap) == 2
    assert crossbar.bar.width == 220 mm and crossbar.bar.height == 40 mm
    assert crossbar.strings.c[1].center.x - crossbar.strings.c[0].center.x == 80 mm
    assert wheel.disc.diameter == 120 mm and wheel.axle.c.diameter == 8 mm
    assert len(windows) == 6
    assert wheel.window.w.radius == 30 mm and wheel.window.w.width == 16 mm
    assert base.name.word.size == 7 mm
    assert distance(base.name, base.left_m) > 2 mm and distance(base.name, base.right_m) > 2 mm
    assert 180 mm + 60 mm < up_h - t, "the wheel hangs below the crossbar"
}
