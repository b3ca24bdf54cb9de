# Request (camping): a tilting tree mount for a trail camera, 6 mm ply (exterior).
# - Tree plate 80 x 160 mm: two vertical strap slots 28 x 6 mm each side (x = +-30 mm, at
#   25 and 140 mm up) for a 25 mm strap round the trunk, two 5.5 mm screw holes on the centre
#   line (20 and 145 mm up) for a lag screw instead, "CAM 01" engraved.
# - Two identical cheeks glued into the tree plate with two tabs each (mortises 7 mm apart),
#   standing 75 mm out; an M6 pivot hole (6.5 mm) 55 mm out at 90 mm up, and an arc slot
#   (radius 25 mm about the pivot, 6.5 mm wide) that lets the camera tilt 30 degrees down and
#   10 degrees up, with engraved ticks every 10 degrees of downward tilt.
# - A 6 mm fin between the cheeks on the M6 pivot, with the M6 lock hole 25 mm below the
#   pivot, glued into a 90 x 80 mm camera platform 25 mm above the pivot (two tabs).
# - The platform has a 6.5 x 24 mm slot for the camera's 1/4"-20 screw beside the fin (centre
#   22 mm off it, so the screw is reached from below) and "FRONT" engraved at the front.

units mm
thickness 6 mm
import "std/joints.aidl"

T = 6 mm
PIVOT_OUT = 55 mm     # pivot from the tree plate's front face
PIVOT_UP = 90 mm      # pivot above the plate's bottom edge
LOCK_R = 25 mm
GAP = 7 mm            # between the cheeks: the fin + 0.5 mm each side
CHEEK_X = GAP / 2 + T / 2   # cheek mid-planes at +-CHEEK_X

# a cheek, drawn with u = out from the tree plate, v = up from the pivot; side = -1 draws it
# mirrored (u to -u) so that its engraved face can look outward on the other side.
# FIX after the first valid program: both cheeks faced "left", so the right cheek's tilt
# ticks faced the fin, 0.5 mm away, where nobody can read them (no message named it).
def cheek(side=1) -> solid {
    body = Hull(Rectangle(bottom_left=(-T, -45), width=12, height=60),
                Circle(center=(side * PIVOT_OUT, 0), radius=15),
                Circle(center=(side * PIVOT_OUT, -24), radius=20))
    tabs = tab_and_slot(part="tab", length=60, thickness=T, tabs=2, tab=15 mm, screw=0,
                        rotation=side * 90 deg, cx=-side * T, cy=-15)
    hole pivot { c = Circle(center=(side * PIVOT_OUT, 0), diameter=6.5) }
    hole lock { s = ArcSlot(center=(side * PIVOT_OUT, 0), radius=LOCK_R,
                            start_angle=(-120 deg if side == 1 else 260 deg),
                            end_angle=(-80 deg if side == 1 else 300 deg), width=6.5) }
    drawing ticks {
        for t in range(4) {
            k = Line((side * (PIVOT_OUT + 31 * cos(-90 deg - t * 10 deg)), 31 * sin(-90 deg - t * 10 deg)),
                     (side * (PIVOT_OUT + 35 * cos(-90 deg - t * 10 deg)), 35 * sin(-90 deg - t * 10 deg)))
        }
    }
    Rigid(self)
}

assembly mount {
    solid plate {
        body = Rectangle(bottom_left=(-40, 0), width=80, height=160)
        hole straps {
            for z in [25, 140] {
                l = Slot(center=(-30, z), length=28, width=6, rotation=90)
                r = Slot(center=(30, z), length=28, width=6, rotation=90)
            }
        }
        hole screws {
            lo = Circle(center=(0, 20), diameter=5.5)
            hi = Circle(center=(0, 145), diameter=5.5)
        }
        ml = tab_and_slot(part="slot", length=60, thickness=T, tabs=2, tab=15 mm, screw=0,
                          rotation=90 deg, cx=-CHEEK_X, cy=PIVOT_UP - 15 mm)
        mr = tab_and_slot(part="slot", length=60, thickness=T, tabs=2, tab=15 mm, screw=0,
                          rotation=90 deg, cx=CHEEK_X, cy=PIVOT_UP - 15 mm)
        drawing name { t = Text("CAM 01", position=(0, 125), size=6, valign="middle") }
        Fixed(body)
    }

    left_cheek = cheek()
    right_cheek = cheek(side=-1)

    # the fin, drawn about the pivot
    solid fin {
        body = Hull(Rectangle(center=(0, 19), width=50, height=24),
                    Circle(center=(0, 0), radius=12),
                    Circle(center=(0, -LOCK_R), radius=9))
        tabs = tab_and_slot(part="tab", length=50, thickness=T, tabs=2, tab=12 mm, screw=0,
                            rotation=0, cx=0, cy=31)
        hole pivot { c = Circle(center=(0, 0), diameter=6.5) }
        hole lock { c = Circle(center=(0, -LOCK_R), diameter=6.5) }
        Rigid(self)
    }

    # the platform, drawn about the point above the pivot
    solid platform {
        body = Rectangle(center=(0, 0), width=90, height=80)
        mortise = tab_and_slot(part="slot", length=50, thickness=T, tabs=2, tab=12 mm, screw=0,
                               rotation=90 deg, cx=0, cy=0)
        hole screw { s = Slot(center=(22, 0), length=24, width=6.5, rotation=0) }
        drawing label { t = Text("FRONT", position=(-25, -32), size=5, valign="middle") }
        Rigid(self)
    }

    # flat layout
    RightOf(left_cheek, plate, gap=6)
    AlignTop(left_cheek, plate)
    Below(right_cheek, left_cheek, gap=6)
    AlignLeft(right_cheek, left_cheek)
    RightOf(fin, left_cheek, gap=6)
    AlignTop(fin, left_cheek)
    Below(platform, right_cheek, gap=6)
    AlignLeft(platform, right_cheek)

    # 3D: x across, the camera looks to -y, the tree is behind (+y), z up
    Place(plate, position=(0, T, 0), face="front", up="up")
    Place(right_cheek, position=(GAP / 2, 0, PIVOT_UP), face="right", up="up")
    Place(left_cheek, position=(-GAP / 2, 0, PIVOT_UP), face="left", up="up")
    Place(fin, position=(T / 2, -PIVOT_OUT, PIVOT_UP), face="left", up="up")
    Place(platform, position=(0, -PIVOT_OUT, PIVOT_UP + 25 mm), face="up", up="back")

    # the request's numbers
    assert plate.body.width == 80 mm and plate.body.height == 160 mm, "plate 80 x 160"
    assert plate.straps.l[0].length == 28 mm, "28 mm strap slots"
    assert plate.mr.slot[0].bb.center_x - plate.ml.slot[0].bb.center_x == GAP + T, "cheeks 7 mm apart"
    assert left_cheek.body.bb.width == 75 mm + T, "cheeks stand 75 mm out (+ tabs)"
    assert left_cheek.pivot.c.center.x - left_cheek.tabs.gap[0].bb.right == 55 mm, "pivot 55 out"
    assert fin.pivot.c.center.y - fin.lock.c.center.y == 25 mm, "lock 25 below the pivot"
    assert platform.body.width == 90 mm and platform.body.height == 80 mm, "platform 90 x 80"
    assert platform.screw.s.center.x - platform.body.center.x == 22 mm, "screw 22 off the fin"
    assert len(left_cheek.ticks.k) == 4, "ticks 0, 10, 20, 30"
}
