# Request: a tilting desk mount for a Raspberry Pi camera module (board 25 x 24, four M2 holes
# 21 mm apart across and 12.5 mm apart up and down), cut from 3 mm acrylic. The camera screws
# to a face plate 44 wide x 36 tall (M2 clearance holes, pattern centred, plus an 18 x 3 slot
# for the ribbon cable 14.5 mm below the centre). Two arms are glued into the back of the face
# plate (one 10 mm tab each, 14.5 mm either side of the centre) and reach 28 mm back to an M3
# pivot; 11 mm below each pivot the arm has an M3 hole for a locking screw. Two cheeks, 28 deep,
# round-topped, hold the pivots 40 mm above the base and carry an arc slot (radius 11 about the
# pivot, 3.4 wide) so the camera tilts 30 deg up and 30 deg down. The cheeks stand 0.5 mm
# outside the arms and are glued into a 60 x 60 base with two 8 mm tabs each. The base screws to
# the desk through two M3 holes countersunk for 6.5 mm heads, 24 mm either side of the centre;
# "CAM" engraved 5 mm tall at its front.

import "std/joints.aidl"
import "std/fasteners.aidl"

thickness 3 mm
T = 3 mm
PIVOT_H = 40 mm     # pivot above the base's top
REACH = 28 mm       # face plate back face to pivot
LOCK_R = 11 mm      # lock screw below the pivot
TILT = 30 deg
ARM_X = 14.5 mm     # arms' centre from the middle
CHEEK_X = ARM_X + T / 2 + 0.5 mm + T / 2   # cheeks' centre from the middle
CHEEK_D = 28 mm

def arm() -> solid {
    bar = Rectangle(bottom_left=(-T, -10), width=REACH + T, height=20)
    boss = Circle(center=(REACH, 0), radius=16)
    tab = tab_and_slot(part="tab", length=20 mm, thickness=T, tabs=1, tab=10 mm, screw=0,
                       rotation=90 deg, cx=-T, cy=0)
    pivot = clearance_hole(size=3, cx=REACH, cy=0)
    lock = clearance_hole(size=3, cx=REACH, cy=-LOCK_R)
    Fixed(bar)
}

def cheek() -> solid {
    # local: x across the depth, y up; y = 0 is the base's top, the tabs reach down through it
    body = RoundedRectangle(bottom_left=(-CHEEK_D / 2, -T), width=CHEEK_D,
                            height=T + PIVOT_H + CHEEK_D / 2,
                            corner_radii=[CHEEK_D / 2, CHEEK_D / 2, 0, 0])
    feet = tab_and_slot(part="tab", length=CHEEK_D, thickness=T, tabs=2, tab=8 mm, screw=0,
                        rotation=180 deg, cx=0, cy=-T)
    pivot = clearance_hole(size=3, cx=0, cy=PIVOT_H)
    hole track {
        a = ArcSlot(center=(0, PIVOT_H), radius=LOCK_R, start_angle=270 deg - TILT,
                    end_angle=270 deg + TILT, width=3.4)
    }
    Fixed(body)
}

assembly mount {
    solid face {
        plate = Rectangle(center=(0, 0), width=44, height=36)
        m2a = clearance_hole(size=2, cx=-10.5, cy=6.25)
        m2b = clearance_hole(size=2, cx=10.5, cy=6.25)
        m2c = clearance_hole(size=2, cx=-10.5, cy=-6.25)
        m2d = clearance_hole(size=2, cx=10.5, cy=-6.25)
        hole cable { s = Slot(center=(0, -14.5), length=18, width=3) }
        left_slot = tab_and_slot(part="slot", length=20 mm, thickness=T, tabs=1, tab=10 mm,
                                 screw=0, rotation=90 deg, cx=-ARM_X, cy=0)
        right_slot = tab_and_slot(part="slot", length=20 mm, thickness=T, tabs=1, tab=10 mm,
                                  screw=0, rotation=90 deg, cx=ARM_X, cy=0)
        Fixed(plate)
        assert plate.bb.width == 44 mm and plate.bb.height == 36 mm, "face plate 44 x 36"
        assert m2b.c.center.x - m2a.c.center.x == 21 mm, "M2 holes 21 across"
        assert m2a.c.center.y - m2c.c.center.y == 12.5 mm, "M2 holes 12.5 up and down"
        assert plate.center.y - cable.s.center.y == 14.5 mm, "cable slot 14.5 below centre"
    }

    left_arm = arm()
    right_arm = arm()
    left_cheek = cheek()
    right_cheek = cheek()

    solid base {
        plate = Rectangle(center=(0, 0), width=60, height=60)
        left_slots = tab_and_slot(part="slot", length=CHEEK_D, thickness=T, tabs=2, tab=8 mm,
                                  screw=0, rotation=90 deg, cx=-CHEEK_X, cy=0)
        right_slots = tab_and_slot(part="slot", length=CHEEK_D, thickness=T, tabs=2, tab=8 mm,
                                   screw=0, rotation=90 deg, cx=CHEEK_X, cy=0)
        left_screw = clearance_hole(size=3, cx=-24, cy=0)
        right_screw = clearance_hole(size=3, cx=24, cy=0)
        Countersink([left_screw, right_screw], diameter=6.5 mm)
        drawing label {
            t = Text("CAM", position=(0, 22), size=5, valign="middle")
        }
        Fixed(plate)
        assert right_screw.c.center.x - left_screw.c.center.x == 48 mm, "screws 24 either side"
    }

    assert left_cheek.pivot.c.center.y - (left_cheek.body.bb.bottom + T) == 40 mm, "pivot 40 above the base"
    assert left_cheek.track.a.radius == 11 mm, "arc slot radius 11"
    assert right_arm.pivot.c.center.x - right_arm.tab.bb.right == 28 mm, "arm reaches 28 back"

    # sheet
    RightOf(left_arm, face, gap=8)
    AlignTop(left_arm, face)
    RightOf(right_arm, left_arm, gap=8)
    AlignTop(right_arm, left_arm)
    Below(left_cheek, face, gap=8)
    AlignLeft(left_cheek, face)
    RightOf(right_cheek, left_cheek, gap=8)
    AlignBottom(right_cheek, left_cheek)
    RightOf(base, right_cheek, gap=8)
    AlignBottom(base, right_cheek)

    # 3D: base flat, camera looking toward +y, pivots on the x axis 40 above the base's top
    Place(base, position=(0, 0, 0))
    Place(left_cheek, rotation=(90 deg, 0, 90 deg), position=(-CHEEK_X - T / 2, 0, T))
    Place(right_cheek, rotation=(90 deg, 0, 90 deg), position=(CHEEK_X - T / 2, 0, T))
    Place(left_arm, rotation=(90 deg, 0, -90 deg), position=(-ARM_X + T / 2, REACH, T + PIVOT_H))
    Place(right_arm, rotation=(90 deg, 0, -90 deg), position=(ARM_X + T / 2, REACH, T + PIVOT_H))
    Place(face, rotation=(90 deg, 0, 180 deg), position=(0, REACH, T + PIVOT_H))
}
