# Request (science): a Shive wave machine for a classroom. 32 bars of 3 mm acrylic, each
# 240 x 12 mm, with a 6.5 x 1.5 mm slot in the middle for a 6 mm flat elastic tape and a
# 4.2 mm hole 10 mm from each end for M4 bolts and nuts as end weights. The tape is
# stretched at 150 mm above the base between two 6 mm ply uprights (60 x 200 mm, an 8 x 2 mm
# tape slot at 150 mm) whose inner faces are 440 mm apart; bars at 13 mm pitch, centred.
# Each upright has two tabs through a 560 x 80 mm base and is held against the tape's pull
# by a triangular brace outside it (50 mm along the base, 100 mm up), tabbed into both.
# "SHIVE WAVE MACHINE" engraved on the base. A 6 mm ply spacing comb 420 x 30 mm with 32
# notches 3.2 mm wide, 12 mm deep at the 13 mm pitch holds the bars while they are glued
# to the tape; "13 mm PITCH" engraved on it.

units mm
thickness 6 mm
import "std/joints.aidl"

T = 6 mm
BAR_T = 3 mm
N = 32
PITCH = 13 mm
INNER = 440 mm       # between the uprights' inner faces
TAPE_Z = 150 mm      # tape above the base's top
BRACE_L = 50 mm
BRACE_H = 100 mm
UP_X = INNER / 2 + T / 2      # uprights' mid-planes at +-UP_X
BRACE_X = INNER / 2 + T + BRACE_L / 2

def bar_x(i) = (i - (N - 1) / 2) * PITCH

def bar() -> solid {
    thickness 3 mm
    body = Rectangle(center=(0, 0), width=240, height=12)
    hole tape { s = Rectangle(center=(0, 0), width=6.5, height=1.5) }
    hole weights {
        l = Circle(center=(-110, 0), diameter=4.2)
        r = Circle(center=(110, 0), diameter=4.2)
    }
    Rigid(self)
}

def upright() -> solid {
    body = Rectangle(bottom_left=(-30, -T), width=60, height=200 + T)
    feet = tab_and_slot(part="tab", length=60, thickness=T, tabs=2, tab=15 mm, screw=0,
                        rotation=180 deg, cx=0, cy=-T)
    brace_mortise = tab_and_slot(part="slot", length=BRACE_H, thickness=T, tabs=2, tab=20 mm,
                                 screw=0, rotation=90 deg, cx=0, cy=BRACE_H / 2)
    hole tape { s = Rectangle(center=(0, TAPE_Z), width=8, height=2) }
    Rigid(self)
}

# u: out from the upright's outer face, v: up from the base's top
def brace() -> solid {
    web = Polygon([(0, 0), (BRACE_L, 0), (0, BRACE_H)])
    foot = Rectangle(bottom_left=(0, -T), width=BRACE_L, height=T)
    back = Rectangle(bottom_left=(-T, 0), width=T, height=BRACE_H)
    bottom_tabs = tab_and_slot(part="tab", length=BRACE_L, thickness=T, tabs=2, tab=10 mm,
                               screw=0, rotation=180 deg, cx=BRACE_L / 2, cy=-T)
    side_tabs = tab_and_slot(part="tab", length=BRACE_H, thickness=T, tabs=2, tab=20 mm,
                             screw=0, rotation=90 deg, cx=-T, cy=BRACE_H / 2)
    Rigid(self)
}

assembly machine {
    solid base {
        body = Rectangle(center=(0, 0), width=560, height=80)
        m_left = tab_and_slot(part="slot", length=60, thickness=T, tabs=2, tab=15 mm, screw=0,
                              rotation=90 deg, cx=-UP_X, cy=0)
        m_right = tab_and_slot(part="slot", length=60, thickness=T, tabs=2, tab=15 mm, screw=0,
                               rotation=90 deg, cx=UP_X, cy=0)
        b_left = tab_and_slot(part="slot", length=BRACE_L, thickness=T, tabs=2, tab=10 mm,
                              screw=0, rotation=0, cx=-BRACE_X, cy=0)
        b_right = tab_and_slot(part="slot", length=BRACE_L, thickness=T, tabs=2, tab=10 mm,
                               screw=0, rotation=0, cx=BRACE_X, cy=0)
        drawing title { t = Text("SHIVE WAVE MACHINE", position=(0, -25), size=8, valign="middle") }
        Fixed(body)
    }

    left_up = upright()
    right_up = upright()
    left_brace = brace()
    right_brace = brace()

    solid comb {
        body = Rectangle(center=(0, 0), width=420, height=30)
        for i in range(N) {
            notch = cross_halving(depth=12, thickness=3.2, cx=bar_x(i), cy=15)
        }
        drawing label { t = Text("13 mm PITCH", position=(0, -8), size=5, valign="middle") }
        Rigid(self)
    }

    for i in range(N) {
        b = bar()
        b.bb.center == (-140 + 250 * (i // 16), -100 - 16 * (i % 16))
    }

    # flat layout of the rest
    Above(left_up, base, gap=6)
    AlignLeft(left_up, base)
    RightOf(right_up, left_up, gap=6)
    AlignBottom(right_up, left_up)
    RightOf(left_brace, right_up, gap=6)
    AlignBottom(left_brace, right_up)
    RightOf(right_brace, left_brace, gap=6)
    AlignBottom(right_brace, left_brace)
    RightOf(comb, right_brace, gap=6)
    AlignBottom(comb, right_brace)

    # 3D: x along the machine, z up; the base's top at z = T
    Place(base, position=(0, 0, 0), face="up", up="back")
    Place(right_up, position=(INNER / 2, 0, T), face="right", up="up")
    Place(left_up, position=(-INNER / 2, 0, T), face="left", up="up")
    Place(right_brace, position=(INNER / 2 + T, T / 2, T), face="front", up="up")
    Place(left_brace, position=(-INNER / 2 - T, -T / 2, T), face="back", up="up")
    for i in range(N) {
        Place(b[i], position=(bar_x(i) - BAR_T / 2, 0, T + TAPE_Z), face="right", up="up")
    }
    Place(comb, position=(0, 60, T), face="up", up="back")

    # the request's numbers
    assert len(b) == 32, "32 bars"
    assert b[0].body.width == 240 mm and b[0].body.height == 12 mm, "bars 240 x 12"
    assert b[0].weights.r.center.x - b[0].weights.l.center.x == 220 mm, "weights 10 from the ends"
    assert bar_x(1) - bar_x(0) == 13 mm, "13 mm pitch"
    assert bar_x(0) + bar_x(N - 1) == 0 mm, "bars centred"
    assert base.m_right.slot[0].bb.center_x - base.m_left.slot[0].bb.center_x == 440 mm + T,
        "inner faces 440 apart"
    assert left_up.tape.s.center.y - left_up.feet.gap[0].bb.top == 150 mm, "tape 150 above the base"
    assert base.body.width == 560 mm and base.body.height == 80 mm, "base 560 x 80"
    assert len(comb.notch) == 32, "32 notches"
    assert comb.body.width == 420 mm, "comb 420 long"
}
