# Request: a hand-cranked pintograph (a drawing machine) for the science club. Base: 6 mm ply
# 320 x 360, R10 corners, with M5 axle holes for three 3 mm acrylic gears of module 2 in a
# row: a 48-tooth gear on the left, a 20-tooth drive gear in the middle (on the base's centre
# line) and a 50-tooth gear on the right, so the two side gears turn at different speeds.
# Each side gear has three 4.3 mm crank-pin holes at 20, 30 and 40 mm from its centre in a
# line; the drive gear has a 6 mm hole 12 mm off centre for a dowel handle. Two arms (3 mm
# acrylic, 18 wide, round ends) each with a pin hole at one end and four 10 mm pen holes
# 170, 185, 200 and 215 mm from it. Set up with both pins at 30 mm straight up and the pen
# in both arms' 200 mm holes, the pen must land inside an A5 sheet (210 x 148) whose
# outline is engraved on the base above the gears, its centre 200 above the drive axle.
# "PINTOGRAPH" engraved above the sheet, "48 : 20 : 50" below the gears.

import "std/gears.aidl"

thickness 3 mm

M = 2 mm
ZL = 48
ZD = 20
ZR = 50
XL = -M * (ZL + ZD) / 2
XR = M * (ZR + ZD) / 2
PIN_R = 30 mm
ARM_HOLE = 200 mm
# pen point with both pins at PIN_R straight up and both arms at their 200 mm hole
HALF = (XR - XL) / 2
PEN_X = XL + HALF
PEN_Y = PIN_R + sqrt(ARM_HOLE ** 2 - HALF ** 2)
ANG_L = atan2(PEN_Y - PIN_R, PEN_X - XL)
ANG_R = atan2(PEN_Y - PIN_R, PEN_X - XR)

def arm() -> solid {
    bar = Slot(start=(0, 0), end=(215, 0), width=18)
    hole pin { c = Circle(center=(0, 0), diameter=4.3) }
    hole pen { c = Circle(center=(170, 0), diameter=10) }
    pens = LinearPattern(pen, 4, (15, 0))
}

def crank_pins(x) -> hole {
    mid = Point(x, 0, construction=true)
    for r in [20, 30, 40] {
        c = Circle(center=(x, r), diameter=4.3)
    }
    Rigid(self)
}

assembly pintograph {
    solid base {
        thickness 6 mm
        board = RoundedRectangle(center=(0, 120), width=320, height=360, corner_radius=10)
        hole axles {
            l = Circle(center=(XL, 0), diameter=5.3)
            d = Circle(center=(0, 0), diameter=5.3)
            r = Circle(center=(XR, 0), diameter=5.3)
        }
        drawing marks {
            paper = Rectangle(center=(0, 200), width=210, height=148)
            title = Text("PINTOGRAPH", position=(0, 287), size=8, valign="middle")
            ratio = Text("48 : 20 : 50", position=(0, -56), size=5, valign="middle")
        }
    }
    g_left = spur_gear(teeth=ZL, module=M, bore=5.3 mm, backlash=0.1 mm, phase=0 deg, mate=ZD,
                       cx=XL, cy=0)
    g_drive = spur_gear(teeth=ZD, module=M, bore=5.3 mm, backlash=0.1 mm, phase=9 deg,
                        mate=ZR, cx=0, cy=0)
    g_right = spur_gear(teeth=ZR, module=M, bore=5.3 mm, backlash=0.1 mm, phase=0 deg,
                        mate=ZD, cx=XR, cy=0)
    arm_l = arm()
    arm_r = arm()

    # the crank-pin and handle holes, cut into the gears wherever the sheet puts them
    pins_l = crank_pins(0)
    Coincident(pins_l.mid, g_left.hub.center)
    CutInto(pins_l, g_left)
    pins_r = crank_pins(0)
    Coincident(pins_r.mid, g_right.hub.center)
    CutInto(pins_r, g_right)
    hole handle {
        mid = Point(0, 0, construction=true)
        c = Circle(center=(12, 0), diameter=6)
        Rigid(self)
    }
    Coincident(handle.mid, g_drive.hub.center)
    CutInto(handle, g_drive)

    # flat: the gears and arms in a column right of the base
    RightOf(g_left, base, gap=10)
    AlignTop(g_left, base)
    Below(g_right, g_left, gap=6)
    AlignLeft(g_right, g_left)
    RightOf(g_drive, g_left, gap=6)
    AlignTop(g_drive, g_left)
    Below(arm_l, g_right, gap=6)
    AlignLeft(arm_l, g_right)
    Below(arm_r, arm_l, gap=6)
    AlignLeft(arm_r, arm_l)

    # in 3D: gears on the base on their axles, arms on the pins, left arm under the right
    Place(base, position=(0, 0, 0), face="up")
    Place(g_left, on=base, position=(0, 0, 6))
    Place(g_drive, on=base, position=(0, 0, 6))
    Place(g_right, on=base, position=(0, 0, 6))
    Place(arm_l, on=base, position=(XL, PIN_R, 9), rotation=(0, 0, ANG_L))
    Place(arm_r, on=base, position=(XR, PIN_R, 12), rotation=(0, 0, ANG_R))

    # the request's numbers
    assert XR - XL == 2 mm * (48 + 20) / 2 + 2 mm * (50 + 20) / 2, "gears in mesh"
    assert base.board.width == 320 mm and base.board.height == 360 mm, "base 320 x 360"
    assert base.board.bb.bottom <= XL * 0 - 2 mm * (48 + 2) / 2 - 5 mm, "left gear on the base"
    assert base.board.bb.right >= XR + 2 mm * (50 + 2) / 2 + 5 mm, "right gear on the base"
    assert abs(PEN_X - base.marks.paper.center.x) <= 210 mm / 2 - 10 mm, "pen over the sheet (x)"
    assert abs(PEN_Y - base.marks.paper.center.y) <= 148 mm / 2 - 10 mm, "pen over the sheet (y)"
    assert base.marks.paper.center.y - base.axles.d.center.y == 200 mm, "sheet 200 above"
    assert base.marks.paper.bb.bottom >= 2 mm * (50 + 2) / 2 + 30 mm + 9 mm, "sheet clear of gears and pins"
    assert len(arm_l.pens) == 4, "four pen holes"
    assert arm_l.pens[2].c.center.x - arm_l.pin.c.center.x == 200 mm, "the 200 mm hole"
}
