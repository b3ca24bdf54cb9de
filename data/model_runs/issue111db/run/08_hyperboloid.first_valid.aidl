# Request: a string hyperboloid for a maths classroom, 3 mm plywood. Two 160 mm discs, each
# with 24 holes of 3 mm on a 140 mm circle (elastic strings run from each hole below to the same
# hole above) and an 8.2 mm centre hole for the 8 mm dowel that joins them (top disc 200 mm
# above the bottom one; twisting it turns the cylinder of strings into a hyperboloid). The top
# disc has an engraved scale for the twist: a 3.5 mm tick every 15 deg just outside the holes
# and the angle (0, 45, ... 315) every 45 deg just inside them. The bottom disc has a filled
# index triangle at the rim. The bottom disc stands 40 mm up on two crossing legs 150 x 40 mm,
# cross-halved 20 + 20, each with two 15 mm tabs glued into mortises in the disc; one leg has
# "HYPERBOLOID" engraved (6 mm).

import "std/joints.aidl"

thickness 3 mm

param holes = 24, min = 12, max = 36
disc_d = 160 mm
hole_circle = 140 mm
leg_len = 150 mm
leg_h = 40 mm
gap = 200 mm

def disc() -> solid {
    body = Circle(center=(0, 0), diameter=disc_d)
    hole axle { c = Circle(center=(0, 0), diameter=8.2) }
    hole string { c = Circle(center=(hole_circle / 2, 0), diameter=3) }
    Fixed(string)
    ring = CircularPattern(string, holes, (0, 0))
}

def top_disc() -> solid {
    d = disc()
    drawing scale {
        for i in range(24) {
            tick = Line((73.5 * cos(i * 15 deg), 73.5 * sin(i * 15 deg)), (77 * cos(i * 15 deg), 77 * sin(i * 15 deg)))
        }
        inner = Circle(center=(0, 0), radius=60, construction=true)
        for a in range(0, 360, 45) {
            num = Text(str(a), along=inner, angle=a * 1 deg, size=4)
        }
    }
}

def bottom_disc() -> solid {
    d = disc()
    along_x = tab_and_slot(part="slot", length=leg_len, thickness=3 mm, tabs=2, tab=15 mm, screw=0,
                           rotation=0 deg, cx=0, cy=0)
    along_y = tab_and_slot(part="slot", length=leg_len, thickness=3 mm, tabs=2, tab=15 mm, screw=0,
                           rotation=90 deg, cx=0, cy=0)
    drawing index {
        arrow = Polygon([(0, 73), (-3, 78), (3, 78)], fill=true)
    }
}

def leg(from_top=false, title=false) -> solid {
    body = Rectangle(center=(0, 0), width=leg_len, height=leg_h)
    tabs = tab_and_slot(part="tab", length=leg_len, thickness=3 mm, tabs=2, tab=15 mm, screw=0,
                        rotation=0 deg, cx=0, cy=leg_h / 2)
    if from_top {
        halving = cross_halving(depth=leg_h / 2, thickness=3 mm, rotation=0 deg, cx=0, cy=leg_h / 2)
    } else {
        halving = cross_halving(depth=leg_h / 2, thickness=3 mm, rotation=180 deg, cx=0, cy=-leg_h / 2)
    }
    if title {
        drawing name {
            word = Text("HYPERBOLOID", position=(0, -10), size=6, valign="middle")
        }
    }
}

assembly hyperboloid {
    bottom = bottom_disc()
    top = top_disc()
    leg_x = leg()
    leg_y = leg(from_top=true, title=true)

    # on the sheet
    Fixed(bottom)
    RightOf(top, bottom, gap=5)
    AlignBottom(top, bottom)
    Below(leg_x, bottom, gap=5)
    AlignLeft(leg_x, bottom)
    RightOf(leg_y, leg_x, gap=5)
    AlignBottom(leg_y, leg_x)

    # in 3D: legs crossing on the floor, the bottom disc on their shoulders, the top disc 200 above
    Place(leg_x, position=(0, 1.5 mm, leg_h / 2), face="front", up="up")
    Place(leg_y, position=(-1.5 mm, 0, leg_h / 2), face="right", up="up")
    Place(bottom, position=(0, 0, leg_h - 3 mm), face="up")
    Place(top, position=(0, 0, leg_h + gap), face="up")

    assert len(bottom.d.ring) == 24 and len(top.d.ring) == 24, "24 string holes a disc"
    assert bottom.d.body.diameter == 160 mm, "160 mm discs"
    assert bottom.d.ring[0].c.diameter == 3 mm, "3 mm string holes"
    assert bottom.d.ring[0].c.center.x - bottom.d.body.center.x == 70 mm, "on a 140 mm circle"
    assert bottom.d.axle.c.diameter == 8.2 mm, "8.2 mm dowel hole"
    assert len(top.scale.tick) == 24 and len(top.scale.num) == 8, "a tick every 15 deg, a number every 45"
    assert leg_x.body.width == 150 mm and leg_x.body.height == 40 mm, "legs 150 x 40"
    assert leg_x.halving.depth + leg_y.halving.depth == 40 mm, "halved 20 + 20"
}
