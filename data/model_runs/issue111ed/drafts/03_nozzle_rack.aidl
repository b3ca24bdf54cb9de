# Request (electronics bench): a rack for the 8 nozzles of a hot-air rework
# station, 3 mm ply. Each nozzle hangs by its collar in a 23 mm hole, holes on a
# 27 mm pitch in one row, 8 mm behind the top plate's centre line. Top plate and
# base both 250 x 60 mm (R5 corners), the top held 40 mm above the base by two
# side panels 60 wide that stand 8 mm in from the ends; each side has two 15 mm
# tenons top and bottom in mortises (0.1 mm clearance). Under each hole, 4 mm
# filled lettering names the nozzle: Ø3 Ø5 Ø7 Ø10 Ø12 4x4 6x6 10x10; and
# "HOT AIR" engraved filled (6 mm) on the outside of each side panel.

import "std/joints.aidl"

units mm
thickness 3 mm

T = 3 mm
L = 250 mm
D = 60 mm
RISE = 40 mm          # clear height between base and top
PITCH = 27 mm
HOLE = 23 mm
N = 8
SIDE_X = L / 2 - 8 mm - T / 2     # side panels' mid-planes
NAMES = ["Ø3", "Ø5", "Ø7", "Ø10", "Ø12", "4x4", "6x6", "10x10"]

def plate(with_holes=0) -> solid {
    body = RoundedRectangle(center=(0, 0), width=L, height=D, corner_radius=5)
    Fixed(body)
    left_mortise = tab_and_slot(part="slot", length=D, thickness=T, tabs=2, tab=15 mm,
                                screw=0, clearance=0.1 mm, rotation=90 deg,
                                cx=-SIDE_X, cy=0 mm)
    right_mortise = tab_and_slot(part="slot", length=D, thickness=T, tabs=2, tab=15 mm,
                                 screw=0, clearance=0.1 mm, rotation=90 deg,
                                 cx=SIDE_X, cy=0 mm)
    if with_holes == 1 {
        hole nozzle {
            c = Circle(center=(-(N - 1) * PITCH / 2, 8), diameter=HOLE)
        }
        holes = LinearPattern(nozzle, N, (PITCH, 0))
        drawing labels {
            for i in range(N) {
                t = Text(NAMES[i], position=(-(N - 1) * PITCH / 2 + i * PITCH, -17), size=4,
                         valign="middle", font="sans:Bold", fill=true)
            }
        }
    }
}

def side() -> solid {
    body = Rectangle(bottom_left=(-D / 2, 0), width=D, height=RISE + 2 * T)
    Fixed(body)
    top_tenons = tab_and_slot(part="tab", length=D, thickness=T, tabs=2, tab=15 mm,
                              screw=0, cx=0 mm, cy=RISE + 2 * T)
    bottom_tenons = tab_and_slot(part="tab", length=D, thickness=T, tabs=2, tab=15 mm,
                                 screw=0, rotation=180 deg, cx=0 mm, cy=0 mm)
    drawing label {
        t = Text("HOT AIR", position=(0, T + RISE / 2), size=6, valign="middle",
                 font="sans:Bold", fill=true)
    }
}

assembly nozzle_rack {
    base = plate(with_holes=0)
    top = plate(with_holes=1)
    left = side()
    right = side()

    # flat on the sheet
    Above(top, base, gap=5)
    AlignCenterX(top, base)
    Above(left, top, gap=5)
    AlignLeft(left, base)
    RightOf(right, left, gap=5)
    AlignBottom(right, left)

    # in 3D
    Place(base, position=(0, 0, 0), face="up")
    Place(top, position=(0, 0, T + RISE), face="up")
    Place(right, position=(SIDE_X - T / 2, 0, 0), face="right", up="up")
    Place(left, position=(-SIDE_X + T / 2, 0, 0), face="left", up="up")

    # the request's numbers
    assert top.body.bb.width == 250 mm and top.body.bb.height == 60 mm, "plates 250 x 60"
    assert len(top.holes) == 8, "8 nozzles"
    assert top.holes[1].c.center.x - top.holes[0].c.center.x == 27 mm, "27 mm pitch"
    assert top.holes[0].c.diameter == 23 mm, "23 mm holes"
    assert top.holes[0].c.center.y - top.body.center.y == 8 mm, "row 8 mm behind the centre line"
    assert left.body.bb.height - 2 * 3 mm == 40 mm, "top 40 above the base"
    assert L / 2 - (SIDE_X + T / 2) == 8 mm, "sides 8 mm in from the ends"
    assert distance(top.holes[7], top.right_mortise) >= 3 mm, "last hole clear of the mortises"
    assert distance(top.labels, top.holes) >= 1.5 mm, "labels clear of the holes"
    assert len(top.labels.t) == 8, "one label per nozzle"
}
