# Request (toys / games): a dice tower for board games, 3 mm ply. A square tower
# 76 x 76 mm outside, 180 mm tall, open at the top: two sides, a front and a back
# finger-jointed at the four corners (15 mm fingers). Inside, two ramps at 35 deg
# tumble the dice: the upper one falls from the front wall towards the back over
# 45 mm (its middle 130 mm up), leaving a gap at the back; the lower one falls from
# the back towards the front over 64 mm (its middle 34 mm up) and throws the dice
# out through an exit in the bottom of the front, 56 mm wide and 50 mm high with
# R6 top corners. Each ramp has two 15 mm tenons each side in angled mortises in
# the sides (0.1 mm clearance). The front carries an engraved d20 (a hexagon
# 24 mm across the corners with its inner triangle) and "ROLL FOR / INITIATIVE"
# filled, 6 mm.

import "std/joints.aidl"

units mm
thickness 3 mm

T = 3 mm
IN = 70 mm             # inside width and depth
OUT = IN + 2 * T       # 76 outside
H = 180 mm
FINGER = 15 mm
ANG = 35 deg
# ramps, in the right side's frame (x = world y, back +), mid-plane middles
R1_SPAN = 45 mm
R1_X = -IN / 2 + 2 mm + R1_SPAN / 2   # from 2 mm off the front wall
R1_Y = 130 mm
R2_SPAN = 64 mm
R2_X = IN / 2 - 1 mm - R2_SPAN / 2    # from 1 mm off the back wall
R2_Y = 34 mm
R1_LEN = R1_SPAN / cos(ANG)
R2_LEN = R2_SPAN / cos(ANG)

# s = 1: right side (its x is world y); s = -1: left side (its x is -world y)
def side(s=1) -> solid {
    body = Rectangle(bottom_left=(-OUT / 2, 0), width=OUT, height=H)
    Fixed(body)
    fr = finger_edge(length=H, thickness=T, finger=FINGER, start="gap", rotation=-90 deg,
                     cx=OUT / 2, cy=H / 2)
    fl = finger_edge(length=H, thickness=T, finger=FINGER, start="gap", rotation=90 deg,
                     cx=-OUT / 2, cy=H / 2)
    # upper ramp: high at the front (-x here), so its line falls towards +x
    m1 = tab_and_slot(part="slot", length=R1_LEN, thickness=T, tabs=2, tab=15 mm, screw=0,
                      clearance=0.1 mm, rotation=s * (-ANG), cx=s * R1_X, cy=R1_Y)
    m2 = tab_and_slot(part="slot", length=R2_LEN, thickness=T, tabs=2, tab=15 mm, screw=0,
                      clearance=0.1 mm, rotation=s * ANG, cx=s * R2_X, cy=R2_Y)
}

# front (with_exit=1) and back
def wall(with_exit=0) -> solid {
    body = Rectangle(bottom_left=(-OUT / 2, 0), width=OUT, height=H)
    Fixed(body)
    fr = finger_edge(length=H, thickness=T, finger=FINGER, start="tab", rotation=-90 deg,
                     cx=OUT / 2, cy=H / 2)
    fl = finger_edge(length=H, thickness=T, finger=FINGER, start="tab", rotation=90 deg,
                     cx=-OUT / 2, cy=H / 2)
    if with_exit == 1 {
        hole exit {
            e = RoundedRectangle(bottom_left=(-28, -1), width=56, height=51,
                                 corner_radii=[6, 6, 0, 0])
        }
        drawing d20 {
            hex = RegularPolygon(center=(0, 150), radius=12, sides=6, rotation=90 deg)
            tri = Triangle((0, 158), (-8, 144), (8, 144))
        }
        drawing words {
            a = Text("ROLL FOR", position=(0, 120), size=6, valign="middle",
                     font="sans:Bold", fill=true)
            b = Text("INITIATIVE", position=(0, 110), size=6, valign="middle",
                     font="sans:Bold", fill=true)
        }
    }
}

def ramp(len=50 mm) -> solid {
    body = Rectangle(center=(0, 0), width=OUT, height=len)
    Fixed(body)
    tl = tab_and_slot(part="tab", length=len, thickness=T, tabs=2, tab=15 mm, screw=0,
                      rotation=90 deg, cx=-OUT / 2, cy=0 mm)
    tr = tab_and_slot(part="tab", length=len, thickness=T, tabs=2, tab=15 mm, screw=0,
                      rotation=-90 deg, cx=OUT / 2, cy=0 mm)
}

assembly dice_tower {
    right = side(s=1)
    left = side(s=-1)
    front = wall(with_exit=1)
    back = wall(with_exit=0)
    upper = ramp(len=R1_LEN)
    lower = ramp(len=R2_LEN)

    # flat on the sheet: a row
    RightOf(left, right, gap=5)
    AlignBottom(left, right)
    RightOf(front, left, gap=5)
    AlignBottom(front, right)
    RightOf(back, front, gap=5)
    AlignBottom(back, right)
    RightOf(upper, back, gap=5)
    AlignBottom(upper, right)
    Above(lower, upper, gap=5)
    AlignLeft(lower, upper)

    # in 3D: the tower's inside is x, y in -35..35, the table z = 0
    Place(front, position=(0, -IN / 2, 0), face="front", up="up")
    Place(back, position=(0, IN / 2, 0), face="back", up="up")
    Place(right, position=(IN / 2, 0, 0), face="right", up="up")
    Place(left, position=(-IN / 2, 0, 0), face="left", up="up")
    # ramps: turned about x; position is the bottom face's middle
    Place(upper, position=(0, R1_X - T / 2 * sin(ANG), R1_Y - T / 2 * cos(ANG)),
          rotation=(-ANG, 0, 0))
    Place(lower, position=(0, R2_X + T / 2 * sin(ANG), R2_Y - T / 2 * cos(ANG)),
          rotation=(ANG, 0, 0))

    # the request's numbers
    assert right.body.bb.width == 76 mm and front.body.bb.width == 76 mm, "76 outside"
    assert front.body.bb.height == 180 mm, "180 tall"
    assert abs(upper.body.bb.height * cos(35 deg) - 45 mm) < 0.01 mm, "upper ramp over 45"
    assert abs(lower.body.bb.height * cos(35 deg) - 64 mm) < 0.01 mm, "lower ramp over 64"
    assert front.exit.e.bb.width == 56 mm, "exit 56 wide"
    assert front.exit.e.bb.top - front.body.bb.bottom == 50 mm, "exit 50 high"
    assert len(right.m1.slot) == 2 and len(upper.tl.gap) == 3, "two tenons a side"
    assert distance(front.words, front.exit) >= 5 mm, "words clear of the exit"
    assert distance(front.d20, front.words) >= 3 mm, "d20 clear of the words"
    # the lower ramp's low end must clear the exit's top (dice roll out under it)
    assert R2_Y - R2_SPAN / 2 * tan(35 deg) + 20 mm < 50 mm, "a 20 mm die leaves under the exit top"
}
