# Request (pets): a bridle rack for the tack room, 9 mm ply. A back plate 150 mm wide and
# 280 mm tall whose top is a full semicircle (r75), screwed to the wall by two 5 mm
# countersunk screws (10 mm heads) on its centre line, 230 mm apart, the lower one 20 mm up
# from the bottom edge. A half-moon former (a half disc of radius 70, its 140 mm straight edge
# against the plate) stands 70 mm out from the plate, its centre 120 mm up from the plate's
# bottom, glued into the plate by three 25 mm tabs through mortises. The horse's name
# "BRAMBLE" engraved filled, 14 mm high in bold sans, centred between the former's top and the
# upper screw.

import "std/fasteners.aidl"
import "std/joints.aidl"

thickness 9 mm

T = 9 mm
plate_w = 150 mm
plate_h = 280 mm
moon_r = 70 mm
moon_y = -plate_h / 2 + 120 mm     # the former's centre on the plate (plate centred at 0)

assembly bridle_rack {
    solid back {
        lower = Rectangle(bottom_left=(-plate_w / 2, -plate_h / 2), width=plate_w,
                          height=plate_h - plate_w / 2)
        arch = Circle(center=(0, plate_h / 2 - plate_w / 2), radius=plate_w / 2)
        top_screw = clearance_hole(size=5)
        low_screw = clearance_hole(size=5)
        AlignCenterX(top_screw, lower)
        AlignCenterX(low_screw, lower)
        VerticalDistance(lower.bottom.midpoint, low_screw.c.center, 20)
        VerticalDistance(low_screw.c.center, top_screw.c.center, 230)
        Countersink([top_screw, low_screw], diameter=10 mm)
        mortise = tab_and_slot(part="slot", length=2 * moon_r, thickness=T, tabs=3, tab=25 mm,
                               screw=0, rotation=90 deg, cx=0 mm, cy=moon_y)
        drawing name {
            t = Text("BRAMBLE", position=(0, 80), size=14, font="sans:Bold", valign="middle",
                     fill=true)
        }
        AlignCenterX(name, lower)
        name.t.position.y == (moon_y + moon_r + top_screw.c.center.y) / 2
    }

    solid former {
        # the straight edge's tab tips on x = -9 (through the plate); the plate's face at x = 0
        moon = Sector(center=(0, 0), radius=moon_r, start_angle=-90 deg, end_angle=90 deg)
        root = Rectangle(bottom_left=(-T, -moon_r), width=T, height=2 * moon_r)
        tabs = tab_and_slot(part="tab", length=2 * moon_r, thickness=T, tabs=3, tab=25 mm,
                            screw=0, rotation=90 deg, cx=-T, cy=0 mm)
    }
    RightOf(former, back, gap=15)

    # 3D: the back plate flat (the wall under it), the former standing out of it along +z
    Place(former, rotation=(0, -90 deg, 0), position=(T / 2, moon_y, T))

    assert back.bb.width == 150 mm, "plate 150 wide"
    assert back.arch.top.y - back.lower.bottom.midpoint.y == 280 mm, "plate 280 tall"
    assert back.top_screw.c.center.y - back.low_screw.c.center.y == 230 mm, "screws 230 apart"
    assert back.low_screw.c.center.y - back.lower.bb.bottom == 20 mm, "lower screw 20 up"
    assert former.moon.radius == 70 mm, "half moon r70"
    assert former.moon.bb.right - former.root.bb.right == 70 mm, "stands 70 out"
    assert back.mortise.bb.center_y - back.lower.bb.bottom == 120 mm, "former 120 up"
}
