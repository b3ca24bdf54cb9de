# Request (sport): a putting-practice ramp for the carpet, 3 mm ply. The ball
# (42.7 mm) rolls up a ramp starting on the floor and rising to a flat green
# 25 mm high (top face) 150 mm further back, then drops into a 60 mm cup hole
# centred 60 mm behind the green's front edge, inside an engraved 80 mm ring.
# The green runs 120 mm, to a back wall. Inside width 120 mm. Two side walls
# stand 20 mm above the ramp and the green (profile: 20 mm at the front, 45 mm
# from the green on), finger-jointed (10 mm) to the 45 mm back wall. The ramp and
# the green each hang from the sides on two 30 mm tabs a side (0.1 mm clearance).
# "19TH HOLE" engraved filled (10 mm) on the back wall's face, above the green.

import "std/joints.aidl"

units mm
thickness 3 mm

T = 3 mm
W = 120 mm                  # inside width
OW = W + 2 * T              # 126: plates with their tabs, back wall
GREEN_TOP = 25 mm
RUN = 149 mm                # the ramp's run (1 mm short of the green)
GREEN_Y0 = 150 mm           # green's front edge from the ramp's foot
GREEN_LEN = 120 mm
BACK_Y = GREEN_Y0 + GREEN_LEN          # back wall's inner face
LEN = BACK_Y + T                       # 273: the sides' length
WALL = 20 mm
RISE = GREEN_TOP - T / 2 - T / 2       # the ramp's mid-plane rise, 1.5 to 23.5
ANG = atan(RISE / RUN)
RAMP_LEN = sqrt(RUN ** 2 + RISE ** 2)

# s = 1: right side (x is world y); s = -1: left side, drawn mirrored
def side(s=1) -> solid {
    body = Polygon([(0, 0), (s * LEN, 0), (s * LEN, GREEN_TOP + WALL),
                    (s * GREEN_Y0, GREEN_TOP + WALL), (0, WALL)])
    Fixed(body)
    back_joint = finger_edge(length=GREEN_TOP + WALL, thickness=T, finger=10 mm,
                             start="gap", rotation=s * (-90 deg), cx=s * LEN,
                             cy=(GREEN_TOP + WALL) / 2)
    ramp_m = tab_and_slot(part="slot", length=RAMP_LEN, thickness=T, tabs=2, tab=30 mm,
                          screw=0, clearance=0.1 mm, rotation=s * ANG,
                          cx=s * RUN / 2, cy=T / 2 + RISE / 2)
    green_m = tab_and_slot(part="slot", length=GREEN_LEN, thickness=T, tabs=2, tab=30 mm,
                           screw=0, clearance=0.1 mm, cx=s * (GREEN_Y0 + GREEN_LEN / 2),
                           cy=GREEN_TOP - T / 2)
}

def hung_plate(len=100 mm) -> solid {
    body = Rectangle(center=(0, 0), width=OW, height=len)
    Fixed(body)
    tl = tab_and_slot(part="tab", length=len, thickness=T, tabs=2, tab=30 mm, screw=0,
                      rotation=90 deg, cx=-OW / 2, cy=0 mm)
    tr = tab_and_slot(part="tab", length=len, thickness=T, tabs=2, tab=30 mm, screw=0,
                      rotation=-90 deg, cx=OW / 2, cy=0 mm)
}

assembly putting_ramp {
    right = side(s=1)
    left = side(s=-1)
    ramp = hung_plate(len=RAMP_LEN)
    green = hung_plate(len=GREEN_LEN)
    hole cup {
        c = Circle(center=(0, 0), diameter=60)
    }
    drawing ring {
        r = Circle(center=(0, 0), diameter=80)
    }
    CutInto(cup, green)
    CutInto(ring, green)
    # the cup's centre 60 mm behind the green's front edge (its -y end, the ramp side)
    AlignCenterX(cup, green)
    cup.c.center.y == green.body.bb.bottom + 60 mm
    Concentric(ring.r, cup.c)

    solid back {
        body = Rectangle(bottom_left=(-OW / 2, 0), width=OW, height=GREEN_TOP + WALL)
        Fixed(body)
        jr = finger_edge(length=GREEN_TOP + WALL, thickness=T, finger=10 mm, start="tab",
                         rotation=-90 deg, cx=OW / 2, cy=(GREEN_TOP + WALL) / 2)
        jl = finger_edge(length=GREEN_TOP + WALL, thickness=T, finger=10 mm, start="tab",
                         rotation=90 deg, cx=-OW / 2, cy=(GREEN_TOP + WALL) / 2)
        drawing words {
            t = Text("19TH HOLE", position=(0, GREEN_TOP + WALL / 2), size=10,
                     valign="middle", font="sans:Bold", fill=true)
        }
    }

    # flat on the sheet
    RightOf(left, right, gap=5)
    AlignBottom(left, right)
    Above(ramp, right, gap=5)
    AlignLeft(ramp, right)
    RightOf(green, ramp, gap=5)
    AlignBottom(green, ramp)
    RightOf(back, green, gap=5)
    AlignBottom(back, ramp)

    # in 3D: x across, y from the ramp's foot to the back, z up
    Place(right, position=(W / 2, 0, 0), face="right", up="up")
    Place(left, position=(-W / 2, 0, 0), face="left", up="up")
    # the ramp turned up by ANG about x; position: its bottom face's middle
    Place(ramp, position=(0, RUN / 2 + T / 2 * sin(ANG), T / 2 + RISE / 2 - T / 2 * cos(ANG)),
          rotation=(ANG, 0, 0))
    Place(green, position=(0, GREEN_Y0 + GREEN_LEN / 2, GREEN_TOP - T), face="up")
    Place(back, position=(0, BACK_Y + T, 0), face="front", up="up")

    # the request's numbers
    assert green.body.bb.height == 120 mm, "green 120 long"
    assert right.body.bb.width == 273 mm, "sides to the back wall's back"
    assert cup.c.diameter == 60 mm and ring.r.diameter == 80 mm, "cup 60, ring 80"
    assert cup.c.center.y - green.body.bb.bottom == 60 mm, "cup 60 behind the green's edge"
    assert back.body.bb.height == 45 mm, "back wall 45"
    assert abs((RAMP_LEN * sin(ANG) + T) - (25 mm - 1.5 mm + 1.5 mm)) < 0.01 mm,
        "ramp rises from the floor to the green's top"
    assert distance(ring, green.tl) >= 3 mm and distance(ring, green.tr) >= 3 mm,
        "ring clear of the tabs"
    assert len(green.tl.gap) == 3, "two tabs a side"
}
