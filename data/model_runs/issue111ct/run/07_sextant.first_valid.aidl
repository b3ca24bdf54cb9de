# Request: a teaching sextant in 3 mm ply (the mirrors are glued-on acrylic, not cut here).
# - Frame: a 70 degree sector of radius 215 mm hanging below its apex (235 to 305 degrees),
#   a 40 mm boss round the apex with a 4.3 mm hole for the M4 pivot bolt, two windows
#   (radius 45 to 150 mm, 245-267 and 273-295 degrees) leaving a centre spoke and the rim.
#   Scale engraved for readings 0 to 120 (a sextant reads double): reading r sits at
#   300 - r/2 degrees; a tick every 5 (from r 186 to 192 mm, every 10 to 196 mm) and the
#   number every 10 on a 205 mm circle, readable from outside the arc. "SEXTANT" engraved
#   on a 165 mm circle at the bottom.
# - Index arm: 20 mm wide, from 40 mm above the pivot to a pointed tip 184 mm below it,
#   4.3 mm pivot hole; "INDEX" engraved along it. Lies on the frame, at reading 0 here.
# - Three upright plates 30 x 40 mm (tenon included), each glued in a 10 mm mortise:
#   the index-mirror mount on the arm, 22 mm above the pivot, along the arm; the horizon-mirror
#   mount on the frame at radius 165 mm, 245 degrees, parallel to the index mirror at reading
#   0; the sight vane at radius 165 mm, 295 degrees, square to the line of sight between them,
#   with a 6 mm peep hole 25 mm above the frame.

import "std/joints.aidl"

thickness 3 mm

param t = 3 mm, min = 2.5 mm, max = 4 mm
zero_deg = 300 deg
arm_turn = zero_deg - 270 deg          # the arm is drawn pointing down (270 deg)
horizon_dir = 90 deg + arm_turn        # the mirrors' direction in plan at reading 0
def at_r(rad, ang) = (rad * cos(ang), rad * sin(ang))
def reading(r) = zero_deg - r / 2 * 1 deg

def mount(peep=false) -> solid {
    plate = Rectangle(center=(0, 20), width=30, height=40)
    tenon = tab_and_slot(part="tab", length=30 mm, thickness=t, tabs=1, tab=10 mm, screw=0,
                         rotation=180 deg, cx=0 mm, cy=0 mm)
    if peep {
        hole eye { c = Circle(center=(0, 25), diameter=6) }
    }
    Fixed(plate)
}

assembly instrument {
    solid frame {
        limb = Sector(center=(0, 0), radius=215, start_angle=235 deg, end_angle=305 deg)
        boss = Circle(center=(0, 0), diameter=40)
        hole pivot { c = Circle(center=(0, 0), diameter=4.3) }
        hole window_l { w = Sector(center=(0, 0), radius=150, start_angle=245 deg,
                                   end_angle=267 deg, inner_radius=45) }
        hole window_r { w = Sector(center=(0, 0), radius=150, start_angle=273 deg,
                                   end_angle=295 deg, inner_radius=45) }
        horizon_slot = tab_and_slot(part="slot", length=30 mm, thickness=t, tabs=1, tab=10 mm,
                                    screw=0, rotation=horizon_dir,
                                    cx=at_r(165, 245 deg)[0], cy=at_r(165, 245 deg)[1])
        vane_slot = tab_and_slot(part="slot", length=30 mm, thickness=t, tabs=1, tab=10 mm,
                                 screw=0, rotation=90 deg,
                                 cx=at_r(165, 295 deg)[0], cy=at_r(165, 295 deg)[1])
        drawing scale {
            ring = Circle(center=(0, 0), radius=205, construction=true)
            for r in range(0, 121, 5) {
                tick = Line(at_r(186, reading(r)), at_r(192 if r % 10 else 196, reading(r)))
            }
            for r in range(0, 121, 10) {
                num = Text(str(r), along=ring, angle=reading(r), size=5, flip=true)
            }
            name_ring = Circle(center=(0, 0), radius=165, construction=true)
            name = Text("SEXTANT", along=name_ring, angle=270 deg, size=7, flip=true)
        }
        Fixed(limb)
        Fixed(scale)
        Fixed(pivot)
        assert limb.radius == 215 mm
        assert len(scale.tick) == 25 and len(scale.num) == 13
        assert boss.diameter == 40 mm and pivot.c.diameter == 4.3 mm
    }

    solid arm {
        bar = Rectangle(bottom_left=(-10, -170), width=20, height=210)
        tip = Polygon([(-10, -170), (10, -170), (0, -184)])
        hole pivot { c = Circle(center=(0, 0), diameter=4.3) }
        mirror_slot = tab_and_slot(part="slot", length=30 mm, thickness=t, tabs=1, tab=10 mm,
                                   screw=0, rotation=90 deg, cx=0 mm, cy=22 mm)
        drawing label { word = Text("INDEX", position=(0, -100), size=8, rotation=90 deg,
                                    valign="middle") }
        Fixed(bar)
        Fixed(pivot)
        Fixed(label)
        assert bar.bb.top - pivot.c.center.y == 40 mm
        assert pivot.c.center.y - tip.bb.bottom == 184 mm
    }

    index_mount = mount()
    horizon_mount = mount()
    vane = mount(peep=true)

    # on the sheet
    RightOf(arm, frame, gap=10)
    AlignTop(arm, frame)
    RightOf(index_mount, arm, gap=10)
    AlignTop(index_mount, frame)
    Below(horizon_mount, index_mount, gap=10)
    AlignLeft(horizon_mount, index_mount)
    Below(vane, horizon_mount, gap=10)
    AlignLeft(vane, index_mount)

    # in 3D: a mount's face normal f is (d_y, -d_x) for its direction d in plan
    Place(frame, position=(0, 0, 0), face="up")
    Place(arm, position=(0, 0, t), rotation=(0, 0, arm_turn))
    im = at_r(22, 90 deg + arm_turn)
    Place(index_mount,
          position=(im[0] - sin(horizon_dir) * t / 2, im[1] + cos(horizon_dir) * t / 2, t),
          face=(sin(horizon_dir), -cos(horizon_dir), 0), up="up")
    hm = at_r(165, 245 deg)
    Place(horizon_mount,
          position=(hm[0] - sin(horizon_dir) * t / 2, hm[1] + cos(horizon_dir) * t / 2, 0),
          face=(sin(horizon_dir), -cos(horizon_dir), 0), up="up")
    vm = at_r(165, 295 deg)
    Place(vane, position=(vm[0] - t / 2, vm[1], 0), face="right", up="up")

    assert vane.eye.c.diameter == 6 mm and vane.eye.c.center.y - t == 22 mm
}
